#pragma once
/// @file Radenkovic's first theorem as the proof that a non-associated increment fails: no flow
/// rule carries a load that associated flow cannot, since any solution's stresses are in
/// equilibrium with the load and within every yield function, whatever the flow that led there.
///
/// Where the LCP of a load-controlled increment with non-associated flow is left undecided (too
/// large for the complete method, and past a limit load, where the active-set method and Lemke
/// prove nothing), the same increment is solved with associated flow: the same yield rows and q,
/// Phi and N from the yield functions' gradients. Its LCP is symmetric, and its certificate r
/// (r >= 0, M_a r = 0, q . r < 0) is a mechanism whose plastic strains are compatible, so that
/// r^T (N - C K^-1 Phi) = 0 for every flow rule Phi of perfect plasticity: the certificate is
/// checked on the non-associated LCP itself before it is used. It proves every load above the
/// associated limit load, not those between the two limit loads.
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/analysis_state.hpp>
#include <bimrock/analysis/increment.hpp>
#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/solve/increment_lcp.hpp>
#include <bimrock/solve/increment_solver.hpp>

namespace bimrock {

struct AssociatedBound {
  IncrementSolution associated;  ///< the associated increment's solve (its work is the trial's)
  Eigen::VectorXd ray;           ///< proven: the associated mechanism's multipliers (>= 0, max 1)
  double proven_fraction = 1.0;  ///< proven: the least fraction of the step proven to fail
  /// Not proven, the associated increment solved, and asked for: the displacements of its flow,
  /// K^-1 Phi_a lambda_a (with the step's load's, those of its state). Else empty.
  Eigen::VectorXd flow_du;
  [[nodiscard]] bool proven() const { return ray.size() > 0; }
};

/// The proof that the increment `lcp` (rows `sys`, of the yield points `candidates` at state s)
/// has no solution, from the associated flow rule. Not proven where its rows follow associated
/// flow already (nothing is solved then), under displacement control, or where the associated
/// increment has a solution or its certificate does not hold on `lcp`. `want_flow`: where the
/// associated increment is solved without a proof, its flow's displacements (flow_du).
AssociatedBound associated_bound(const StageContext& ctx, const AnalysisState& s,
                                 const std::vector<int>& candidates, const YieldSystem& sys,
                                 const IncrementLcp& lcp, IncrementSolver& solver,
                                 bool want_flow = false);

}  // namespace bimrock
