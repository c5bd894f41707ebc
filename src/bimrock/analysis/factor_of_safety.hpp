#pragma once
/// @file The factor of safety by strength reduction, what is asked and what is found: from the
/// equilibrium state the stages reached, the strengths are divided by F = 1 + dF, 1 + 2 dF, ...
/// (strength_reduction.hpp), each step one increment of LCPs with no load on the same factor of
/// K, until a step is proven to have no solution; that step is bisected until the largest F
/// carried and the smallest F proven to fail are within the tolerance. Where the stages
/// themselves collapse, F < 1: each trial runs them again with the strengths divided by F < 1
/// (factor_of_safety_search.hpp).
#include <functional>
#include <optional>
#include <vector>

#include <bimrock/analysis/collapse.hpp>
#include <bimrock/analysis/strength_reduction.hpp>
#include <bimrock/geometry/vec2.hpp>

namespace bimrock {

struct FactorOfSafetyOptions {
  StrengthSelection selection;  ///< the materials reduced (empty vectors: every one with a law)
  double tolerance = 1e-3;      ///< relative width of the bracket [lower, upper]
  double step = 0.05;           ///< the increment of F between trials
  double largest = 10.0;        ///< F is not raised beyond this
  /// The stage after which F is found (its index; none: the last); later stages then go on
  /// from the state at F = 1.
  std::optional<int> after_stage;
};

/// One trial of F that carried: F, the largest plastic multiplier of its step (a slip or an
/// opening [m]), and the monitors' displacements since F = 1 [m].
struct FactorTrial {
  double factor = 1.0;
  double largest_flow = 0.0;
  std::vector<Vec2> monitors;
};

/// Called after every F the search carried (e.g. to report progress).
using FactorTrialCallback = std::function<void(const FactorTrial&)>;

struct FactorOfSafety {
  int stage = 0;         ///< the stage after which F was found
  double lower = 1.0;    ///< the largest F shown stable (carried)
  double largest = 1.0;  ///< the largest F the search would try (FactorOfSafetyOptions)
  /// The smallest F proven to fail (collapse->failed; collapse->carried is `lower`) and its
  /// mechanism; none where the structure carries F = `largest` (or a step was undecided).
  std::optional<Collapse> collapse;
  /// A step was neither carried nor proven to fail (round-off near the limit), and the search
  /// ended there. Above 1: F is at least `lower`, and no upper bound was proven. Below 1: F is
  /// below collapse->failed, the smallest F proven to fail, and at least `lower`, the largest
  /// carried (0: none).
  bool undecided = false;
  std::vector<FactorTrial> trials;  ///< F = 1 and every F carried, in order
};

}  // namespace bimrock
