#pragma once
/// @file The search for the factor of safety (factor_of_safety.hpp) after the stages of a
/// plastic analysis, on the analysis' factor of K and solver.
#include <functional>
#include <optional>
#include <vector>

#include <bimrock/analysis/factor_of_safety.hpp>
#include <bimrock/analysis/increment.hpp>
#include <bimrock/solve/spd_solver.hpp>

namespace bimrock {

/// The materials whose strength `fos` reduces (every one with a strength law by default).
StrengthSelection selected_strengths(const Model& model, const FactorOfSafetyOptions& fos);

/// F from `start`, the equilibrium state of `model` after its stages. `model` and `points` are
/// the analysis' (the reduced models share their geometry and K); `present`, if given, the
/// blocks and bolts present (after excavations and installations).
FactorOfSafety find_factor_of_safety(const Model& model, const std::vector<YieldPoint>& points,
                                     const SpdSolver& k, const AnalysisState& start,
                                     const FactorOfSafetyOptions& fos,
                                     const PlasticOptions& options, const CandidateTuning& tuning,
                                     IncrementSolver& solver, IncrementMemory& memory,
                                     Timings& timings, const FactorTrialCallback& on_trial = {},
                                     const Presence* present = nullptr);

/// The stages of a model, run again from the unloaded state with its strengths divided by a
/// factor: carried (with the state at their end and its largest accumulated plastic slip),
/// collapsed (with the collapse), or neither (undecided).
struct StagesOutcome {
  AnalysisState state;
  double largest_flow = 0.0;
  std::optional<Collapse> collapse;
  bool undecided = false;
};
using RunStages = std::function<StagesOutcome(double factor)>;

/// F < 1, for a structure that collapses under its stages with the strengths as given
/// (`at_one`): each trial runs the stages again with the strengths divided by F (raised), F
/// lowered from 1 in steps of `fos.step` down to 1 / `fos.largest` until the stages carry, then
/// bisected between the largest F that carries them and the smallest that collapses, to
/// `fos.tolerance`. `lower` is 0 where even 1 / `fos.largest` collapses.
FactorOfSafety find_factor_below_one(const Model& model, const FactorOfSafetyOptions& fos,
                                     const Collapse& at_one, const RunStages& run,
                                     const FactorTrialCallback& on_trial = {});

}  // namespace bimrock
