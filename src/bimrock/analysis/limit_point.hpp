#pragma once
/// @file Past a load that load control leaves undecided: the stage goes on under displacement
/// control, to the limit point of its equilibrium path.
///
/// Near a limit load of non-associated flow a load-controlled increment can have no solution and
/// no proof that it has none: associated flow's certificate proves only the loads above the
/// associated limit load (associated_bound.hpp), and the complete method's search outgrows its
/// budget on large LCPs. Under displacement control the load factor is an unknown of the
/// increment (still one LCP): it rises to the limit load and levels off there (perfect
/// plasticity: a mechanism forms) or falls past it (softening). Its largest value is the limit
/// point of the equilibrium path, which the analysis reports as the collapse load.
///
/// The point controlled is the centroid of the block that moved most in the last increment
/// carried, along its motion: near a limit load that motion is the mechanism's.
#include <optional>

#include <Eigen/Core>

#include <bimrock/analysis/load_stepping.hpp>
#include <bimrock/geometry/vec2.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

/// A point of a block and the direction its displacement is measured along.
struct ControlPoint {
  int block = -1;  ///< -1: no block moves
  Vec2 direction = Vec2::Zero();
};

/// The block whose centroid moves most in `du` (the model's unknowns, 6 a block), and the
/// direction of that motion.
[[nodiscard]] ControlPoint most_moved_block(const Model& model, const Eigen::VectorXd& du);

struct LimitPointOptions {
  double step = 0.0;       ///< the displacement prescribed in each increment
  double stage_end = 1.0;  ///< the stage factor of the stage's full load
  SteppingOptions stepping;
  /// The load factor has levelled off once it stays within the bracket tolerance of its largest
  /// value while the controlled point moves this far (a mechanism of perfect plasticity). A path
  /// that cannot be followed further (an increment left undecided, or proven to have no
  /// solution under displacement control) after three increments on its plateau ends there too,
  /// at the plateau's length.
  double plateau = 0.0;
  int most_increments = 50;
};

struct LimitPoint {
  enum class Outcome {
    limit_point,  ///< the load factor levelled off or fell: `peak` is the limit load
    rises,        ///< the load factor would pass the stage's end: its load is carried on
    undecided,    ///< no limit point within most_increments, or an increment left undecided
  };
  Outcome outcome = Outcome::undecided;
  double peak = 0.0;     ///< the largest stage factor carried
  double plateau = 0.0;  ///< how far the point moved with the load factor at its peak
  bool fell = false;     ///< limit_point: the load factor fell past its peak
  /// The last increment carried under displacement control: at a limit point, its flow is
  /// the mechanism.
  std::optional<Trial> last;
};

/// Follows the equilibrium path from stage factor `factor` by increments of prescribed
/// displacement (`try_controlled`), carrying each (`carry`) until the load factor levels off,
/// falls, or would pass the stage's end. An increment that would pass the stage's end is not
/// carried: load control goes on from the state before it. A path of non-associated flow is
/// not unique, and one that levels off can rise again further on (a joint that opened closes):
/// a plateau is a limit point only as long as options.plateau.
[[nodiscard]] LimitPoint follow_to_limit_point(double factor, const TryStep& try_controlled,
                                               const CarryStep& carry,
                                               const LimitPointOptions& options);

}  // namespace bimrock
