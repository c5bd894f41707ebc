#pragma once
/// @file What a user sets for a plastic analysis (the case file's `analysis:` section), apart
/// from the expert tuning of the solution strategy, whose defaults are the method's.
#include <optional>

#include <bimrock/analysis/candidates.hpp>
#include <bimrock/analysis/factor_of_safety.hpp>
#include <bimrock/solve/increment_solver.hpp>
#include <bimrock/solve/stiffness_factor.hpp>

namespace bimrock {

struct PlasticOptions {
  /// A failed increment is bisected until the collapse bracket is this narrow (relative).
  double bracket_tolerance = 1e-4;
  /// At most this many bisections per increment.
  int max_bisections = 40;
  /// Rounds of "solve, check every yield function, add the violated points" per increment.
  int max_rounds = 30;
  /// A yield function counts as violated above this fraction of the stress scale (the largest
  /// stress component or strength met).
  double yield_tolerance = 1e-9;
  /// After the stages, the factor of safety by strength reduction (none: not sought).
  std::optional<FactorOfSafetyOptions> factor_of_safety;
};

/// Expert tuning of the solution strategy: the candidates of each LCP, and how it is solved.
/// Tests change it to compare routes; an analysis needs the defaults.
struct PlasticTuning {
  CandidateTuning candidates{};
  SolverTuning solver{};
  /// Where K is factorized (solve/stiffness_factor.hpp): empty, by CHOLMOD in this process; the
  /// PETSc backend's factorizes it across the processes of an MPI run
  /// (petsc/distributed_factor.hpp).
  StiffnessFactorization stiffness{};
  /// Where load control leaves a load undecided, at most this many increments of displacement
  /// control look for the limit point of the equilibrium path (analysis/limit_point.hpp); 0:
  /// the analysis stops there.
  int limit_point_increments = 100;
};

}  // namespace bimrock
