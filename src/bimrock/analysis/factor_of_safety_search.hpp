#pragma once
/// @file The search for the factor of safety (factor_of_safety.hpp) after the stages of a
/// plastic analysis, on the analysis' factor of K and solver.
#include <vector>

#include <bimrock/analysis/factor_of_safety.hpp>
#include <bimrock/analysis/increment.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

/// F from `start`, the equilibrium state of `model` after its stages. `model` and `points` are
/// the analysis' (the reduced models share their geometry and K).
FactorOfSafety find_factor_of_safety(const Model& model, const std::vector<YieldPoint>& points,
                                     const SparseCholesky& k, const AnalysisState& start,
                                     const FactorOfSafetyOptions& fos,
                                     const PlasticOptions& options, const CandidateTuning& tuning,
                                     IncrementSolver& solver, IncrementMemory& memory,
                                     Timings& timings, const FactorTrialCallback& on_trial = {});

}  // namespace bimrock
