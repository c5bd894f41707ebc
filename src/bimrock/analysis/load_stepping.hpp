#pragma once
/// @file Load stepping: one increment of a stage carried whole, in parts, or bracketed. A step
/// that a softening law's kink cuts is carried to the kink and then on. A step that fails is
/// bisected: parts that carry are kept, and the collapse load is bracketed between the largest
/// factor carried and the nearest one proven to fail, to a relative tolerance. A step that fails
/// only numerically (no solution found, none proven absent) proves nothing: it is cut, and once a
/// part of it has carried the rest is tried again from the new state (where that fails too, the
/// next parts grow from the last one).
#include <functional>
#include <optional>

#include <bimrock/analysis/collapse.hpp>
#include <bimrock/analysis/increment.hpp>

namespace bimrock {

struct SteppingOptions {
  double bracket_tolerance = 1e-4;  ///< relative width of the collapse bracket
  int max_bisections = 40;
  bool displacement_control = false;  ///< the step is a prescribed displacement
  /// Nothing has been carried yet in the analysis: a failure proven within the bracket
  /// tolerance of zero load is an instability under the first load, not a bracket.
  bool first_load = false;
  /// Load control: the stage factor at the stage's end. Where the cuts of a step end undecided
  /// without a proof, trials from the load carried look for a proof above (a certificate, or
  /// associated flow's for non-associated flow: docs/formulation.md), the first to there, each
  /// next one half as far; found, the collapse is bracketed, with undecided trials inside.
  /// Empty: none.
  std::optional<double> stage_end{};
};

struct SteppedIncrement {
  enum class Outcome {
    carried,    ///< the whole increment is carried (in one part or several)
    collapse,   ///< proven: the load in [carried, failed] is the collapse load
    undecided,  ///< neither carried nor proven to fail (round-off near a limit load)
  };
  Outcome outcome = Outcome::carried;
  double carried = 0.0;                 ///< the stage factor carried
  double failed = 0.0;                  ///< collapse: the nearest stage factor proven to fail
  std::optional<Trial> failure;         ///< collapse: the trial that proved it
  bool unstable_at_first_load = false;  ///< collapse proven within the tolerance of zero load
  /// collapse: the bisection ended on undecided trials, the bracket wider than the tolerance
  bool undecided_inside = false;
};

/// Tries a step from the state carried so far, its LCPs solved as thoroughly as asked: inside a
/// bracket already proven, a trial that stays undecided moves no bound, and is tried quick.
using TryStep = std::function<Trial(double step, Thoroughness thoroughness)>;
/// Carries a trial: its state becomes the one the next step starts from.
using CarryStep = std::function<void(const Trial&)>;

/// Carries one increment of `step` from stage factor `factor`.
SteppedIncrement step_increment(double step, double factor, const TryStep& try_step,
                                const CarryStep& carry, const SteppingOptions& options);

/// The collapse of stage `stage` in [carried, failed], with the mechanism of the failed trial
/// where it has a certificate, else the flow of the last carried trial (near a collapse it is
/// dominated by the mechanism).
Collapse describe_collapse(int stage, double carried, double failed, const Trial* failure,
                           const Trial* last);

}  // namespace bimrock
