#include <bimrock/analysis/associated_bound.hpp>

#include <bimrock/analysis/step_certificate.hpp>

namespace bimrock {

AssociatedBound associated_bound(const StageContext& ctx, const AnalysisState& s,
                                 const std::vector<int>& candidates, const YieldSystem& sys,
                                 const IncrementLcp& lcp, IncrementSolver& solver, bool want_flow) {
  AssociatedBound bound;
  if (lcp.control || sys.size() == 0 || follows_associated_flow(sys))
    return bound;
  // The same increment with associated flow: f0 and C, and so q, do not depend on the flow.
  const YieldSystem associated =
      assemble_yield_system(ctx.model, ctx.points, s.points, s.u, candidates, FlowRule::associated);
  const IncrementLcp alcp{associated, lcp.points, lcp.q,    lcp.load_part, lcp.gap_old,
                          nullptr,    {},         lcp.warm, nullptr,       {}};
  bound.associated = solver.solve(alcp, nullptr, false);
  const IncrementSolution& a = bound.associated;
  // The candidate: associated flow's certificate, or its solution's flow where round-off
  // resolved the mechanism as a very soft mode (multipliers orders of magnitude above the
  // step's, as increment.cpp says). Any r >= 0 that passes the check below is a proof.
  using Outcome = IncrementSolution::Outcome;
  Eigen::VectorXd r;
  if (a.outcome == Outcome::no_solution && a.ray.size() == sys.size())
    r = a.ray;
  else if (a.outcome == Outcome::solved && a.z.size() == sys.size()) {
    const Eigen::VectorXd lambda = a.z - lcp.gap_old;
    if (want_flow)
      bound.flow_du = ctx.k.solve(Eigen::VectorXd(associated.phi * lambda));
    r = lambda.cwiseMax(0.0);
  }
  if (r.size() == 0 || !(r.maxCoeff() > 0.0))
    return bound;
  r /= r.maxCoeff();
  // The certificate on the non-associated LCP itself.
  const std::optional<double> fraction = certified_step_fraction(ctx, sys, lcp, r);
  if (!fraction)
    return bound;
  bound.ray = r;
  bound.proven_fraction = *fraction;
  return bound;
}

}  // namespace bimrock
