#include <bimrock/solve/least_norm_pivoting.hpp>

#include <algorithm>
#include <vector>

#include <Eigen/QR>

namespace bimrock {

using Index = Eigen::Index;

/// How much larger than the first round's set a later round's may be: kLargestGrowth times it,
/// and kExtraRows more (on small LCPs the first set can be half the solution's, and their rounds
/// cost next to nothing).
constexpr double kLargestGrowth = 1.5;
constexpr double kExtraRows = 50.0;

std::optional<LcpResult> least_norm_pivoting(const LcpProblem& p, const Eigen::VectorXd& near,
                                             double accuracy, int rounds, int steps) {
  const RelativePairs rel = relative_pairs(p, near);
  std::vector<char> in_a(static_cast<std::size_t>(p.size()));
  for (Index i = 0; i < p.size(); ++i)
    in_a[static_cast<std::size_t>(i)] = rel.z(i) > rel.w(i);
  Eigen::VectorXd corrected = near;
  double first_size = 0.0;  // rows of the first round's set
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
    // Near a solution the sets stay within a few rows of the first; sets that grow far beyond
    // it are drifting away, and each round costs the cube of its size.
    const auto next_size = static_cast<double>(std::count(in_a.begin(), in_a.end(), char{1}));
    if (round == 0)
      first_size = static_cast<double>(active.size());
    if (!moved || next_size > kLargestGrowth * first_size + kExtraRows)
      break;
  }
  return std::nullopt;
}

}  // namespace bimrock
