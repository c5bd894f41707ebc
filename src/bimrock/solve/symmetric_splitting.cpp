#include <bimrock/solve/symmetric_splitting.hpp>

#include <algorithm>
#include <limits>

namespace bimrock {

SplittingResult solve_by_splitting(const Eigen::VectorXd& q, const SplittingRemainder& remainder,
                                   const SymmetricLcpSolve& solve_symmetric,
                                   const ActiveSetProposal& propose, const Eigen::VectorXd& start,
                                   const Eigen::VectorXd* warm, const SplittingOptions& options) {
  SplittingResult out;
  const Eigen::Index n = q.size();
  Eigen::VectorXd active = warm ? *warm : Eigen::VectorXd::Zero(n);
  Eigen::VectorXd proposed;  // the last active set tried
  Eigen::VectorXd z = start;
  double relaxation = 1.0;
  int stalled = 0;  // iterates in a row that changed no fewer rows than the least so far
  Eigen::Index least = std::numeric_limits<Eigen::Index>::max();
  for (int k = 0; k < options.max_iterations; ++k) {
    const LcpResult inner =
        solve_symmetric(Eigen::VectorXd(q + remainder(z)), k == 0 && !warm ? nullptr : &active);
    if (inner.status != LcpStatus::solved || inner.z.size() != n)
      return out;
    out.z = inner.z;
    ++out.iterations;
    const Eigen::VectorXd now = (inner.z.array() > 0.0).cast<double>();
    const auto changed = static_cast<Eigen::Index>((now - active).cwiseAbs().sum());
    active = now;
    // The active set {i : z_i > 0} held from the last iterate: a proposal (each set once).
    if (k > 0 && changed == 0 && (proposed.size() != n || active != proposed)) {
      proposed = active;
      ++out.proposals;
      if (propose(active)) {
        out.solved = true;
        return out;
      }
    }
    // Iterates that swap rows back and forth (the iteration matrix has an eigenvalue near -1)
    // are damped: z moves only part of the way to the inner solution from then on.
    stalled = k > 0 && changed >= least ? stalled + 1 : 0;
    if (k > 0)
      least = std::min(least, changed);
    if (stalled >= options.stalled_after && relaxation > options.least_relaxation) {
      relaxation /= 2.0;
      stalled = 0;
      least = changed;
    }
    z += relaxation * (inner.z - z);
  }
  return out;
}

}  // namespace bimrock
