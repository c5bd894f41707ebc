#pragma once
/// @file What a collapse is reported with: the bracket of the collapse load and the mechanism.
#include <vector>

#include <Eigen/Core>

namespace bimrock {

/// One active yield mode of a collapse mechanism.
struct MechanismEntry {
  int point = 0;
  int mode = 0;
  double multiplier = 0.0;  ///< normalized to the largest
};

/// The structure could not carry a load increment: the collapse load lies in
/// [carried, failed] (stage factors) and the mechanism is that of the last carried step, or
/// the load factor reached the peak of its equilibrium path (limit_point).
struct Collapse {
  int stage = 0;
  double carried = 0.0;
  double failed = 0.0;
  std::vector<MechanismEntry> mechanism;
  Eigen::VectorXd direction;  ///< displacement increment of the last carried step, unit norm
  /// Nothing of the first stage could be carried: the structure is proven to fail under a
  /// fraction of its first load no larger than the bracket tolerance (e.g. a cohesionless arch
  /// thinner than its least thickness under its own weight). `failed` is that fraction.
  bool unstable_at_first_load = false;
  /// The loads inside [carried, failed] could not be decided (neither carried nor proven to
  /// fail; analysis/load_stepping.hpp): the bracket is wider than the tolerance. Non-associated
  /// flow proven by associated flow's certificate ends so, between its two limit loads.
  bool undecided_inside = false;
  /// Load control stopped undecided at `carried`, and `failed` is the collapse load of the same
  /// case with associated flow (each dilation equal to its friction), an upper bound of this
  /// one's by the static theorem (analysis/strength_reduction.hpp, with_associated_flow); the
  /// mechanism is associated flow's. undecided_inside is set too.
  bool associated_bound = false;
  /// The limit point of the equilibrium path: load control left a load undecided, and under
  /// displacement control the load factor levelled off or fell (analysis/limit_point.hpp).
  /// carried = failed = its largest value; the mechanism is the flow of the last increment.
  bool limit_point = false;
  int control_block = -1;  ///< limit_point: the block whose motion was prescribed
  double plateau = 0.0;    ///< limit_point: how far its centroid moved at the limit load [m]
  bool fell = false;       ///< limit_point: the load factor fell past its peak
  double elastic = 0.0;    ///< limit_point: how far the stage's whole load moves it elastically [m]
};

}  // namespace bimrock
