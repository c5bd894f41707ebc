#include <bimrock/solve/least_norm_pivoting.hpp>

#include <vector>

#include <Eigen/QR>

namespace bimrock {

using Index = Eigen::Index;

std::optional<LcpResult> least_norm_pivoting(const LcpProblem& p, const Eigen::VectorXd& near,
                                             double accuracy, int rounds, int steps) {
  const RelativePairs rel = relative_pairs(p, near);
  std::vector<char> in_a(static_cast<std::size_t>(p.size()));
  for (Index i = 0; i < p.size(); ++i)
    in_a[static_cast<std::size_t>(i)] = rel.z(i) > rel.w(i);
  Eigen::VectorXd corrected = near;
  for (int round = 0; round < rounds; ++round) {
    std::vector<Index> active;
    for (Index i = 0; i < p.size(); ++i)
      if (in_a[static_cast<std::size_t>(i)])
        active.push_back(i);
    Eigen::VectorXd fresh = Eigen::VectorXd::Zero(p.size());
    if (!active.empty()) {
      const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> m_aa(p.m(active, active));
      for (int k = 0; k < 2; ++k) {
        const Eigen::VectorXd w = p.m * corrected + p.q;
        const Eigen::VectorXd dz = m_aa.solve(Eigen::VectorXd(w(active)));
        corrected(active) -= dz;
      }
      const Eigen::VectorXd z_active = m_aa.solve(Eigen::VectorXd(-p.q(active)));
      fresh(active) = z_active;
    }
    for (Index i = 0; i < p.size(); ++i)
      if (!in_a[static_cast<std::size_t>(i)])
        corrected(i) = 0.0;
    for (const Eigen::VectorXd& candidate : {corrected, fresh, near}) {
      LcpResult r = make_lcp_result(p, LcpStatus::solved, candidate, steps);
      if (r.residuals.worst_relative() <= accuracy)
        return r;
    }
    const RelativePairs now = relative_pairs(p, corrected);
    bool moved = false;
    for (Index i = 0; i < p.size(); ++i) {
      char& a = in_a[static_cast<std::size_t>(i)];
      if (a ? now.z(i) < -accuracy : now.w(i) < -accuracy) {
        a = !a;
        moved = true;
      }
    }
    if (!moved)
      break;
  }
  return std::nullopt;
}

}  // namespace bimrock
