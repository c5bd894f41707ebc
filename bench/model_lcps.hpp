#pragma once
// Dense LCPs of single load increments of our own models, for comparing LCP solvers on the
// problems bimrock really solves (bench/siconos_lcp_bench.cpp). Built with the library's public
// API only (build_model, assemble_stiffness_lower, SparseCholesky, make_yield_points,
// assemble_yield_system, run_plastic_analysis and the point kernels of yield_modes.hpp), the way
// analysis/plastic_analysis.cpp forms the LCP of a load-controlled increment (eqs. 24, 28):
//   M = N - C K^-1 Phi,   q = -f0 - C x_ref step - M gap_old,
// x_ref = K^-1 P_stage, gap_old the openings of the candidate joints before the increment (the
// opening multiplier is the total gap, not its increment).
#include <string>

#include <bimrock/solve/lcp.hpp>

namespace bimrock::bench {

/// One LCP and where it comes from.
struct ModelLcp {
  std::string model;   ///< short name: "brick mass", "wall near collapse", "wall at its limit"
  std::string source;  ///< model, state and increment, for reports
  LcpProblem problem;
  /// The warm start the analysis gives the active-set method: the openings before the increment
  /// on the opening rows (z of an opening row is the total gap), zero elsewhere; empty when no
  /// joint was open (the analysis then starts it cold).
  Eigen::VectorXd warm_start;
  int blocks = 0;
  /// Rows of the last LCP the analysis itself solved in that increment (IncrementRecord), for
  /// comparison: ours holds the points that yield in the increment and those whose elastic
  /// predictor exceeds yield (or that are open), so it has as many rows or fewer.
  int analysis_rows = 0;
  /// How the analysis solved its LCP of that increment: active-set iterations, and Lemke pivots
  /// (non-zero when the active-set method failed and Lemke took over).
  int analysis_active_set_iterations = 0;
  int analysis_pivots = 0;
  bool symmetric = false;  ///< associated flow: M symmetric (to round-off)
};

/// (a) The free-standing brick mass of bench/brick_mass.hpp with no-tension plastic joints
/// (non-associated: friction 35 deg, no dilation), the first of 5 gravity increments, from the
/// unloaded state. About 2.8 rows per block: the vertical joints of the free-standing mass, which
/// carry no normal stress, open. The same rows as the analysis' own LCP of that increment, to
/// within 1 %.
ModelLcp brick_mass_gravity_lcp(int n_blocks);

/// (b) The jointed wall of reference/reference_cases.hpp (wall_case: associated Mohr-Coulomb joints
/// with a tension cut-off) pushed sideways to 1.3 times the sliding load of its top row in 10
/// steps: the last increment the analysis carries before the collapse (a bisected step, from
/// 0.91 to 0.975 of the sliding load), from the state the analysis reached (run_plastic_analysis,
/// captured through its increment callback). About 7 rows per block at 100 blocks, 4 at 460 (the
/// plastic zone is at the top).
ModelLcp wall_near_collapse_lcp(int n_blocks);

/// (c) The same wall pushed to 1.25 times the sliding load in 10 steps, as docs/performance.md's
/// run (25 steps there): the LCP of the 8th step, which ends exactly at the sliding load. Our
/// active-set method fails on it (numerical_failure: after 6 iterations warm-started, after 1
/// cold), although the active block at the solution is well conditioned (at 100 blocks its
/// eigenvalues span 2.9e7 to 9.6e10), and the analysis falls back to Lemke.
ModelLcp wall_at_limit_lcp(int n_blocks);

}  // namespace bimrock::bench
