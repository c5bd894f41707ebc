#include <bimrock/solve/active_set_lcp.hpp>

#include <set>
#include <stdexcept>
#include <vector>

#include <Eigen/LU>

namespace bimrock {

LcpResult ActiveSetLcp::solve(const LcpProblem& problem, const Eigen::VectorXd* warm_start) {
  check_lcp(problem);
  const Eigen::Index n = problem.size();
  if ((problem.q.array() >= 0.0).all())
    return make_lcp_result(problem, LcpStatus::solved, Eigen::VectorXd::Zero(n), 0);
  if (warm_start != nullptr && warm_start->size() != n)
    throw std::invalid_argument("active-set LCP: warm start of the wrong size");

  std::vector<char> active(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    active[static_cast<std::size_t>(i)] = warm_start ? (*warm_start)(i) > 0.0 : problem.q(i) < 0.0;
  std::set<std::vector<char>> seen;  // an active set met twice is a cycle
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    if (!seen.insert(active).second)
      return make_lcp_result(problem, LcpStatus::iteration_limit, z, iteration);
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < n; ++i)
      if (active[static_cast<std::size_t>(i)])
        rows.push_back(i);
    const auto k = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd a(k, k);
    Eigen::VectorXd rhs(k);
    for (Eigen::Index r = 0; r < k; ++r) {
      rhs(r) = -problem.q(rows[static_cast<std::size_t>(r)]);
      for (Eigen::Index c = 0; c < k; ++c)
        a(r, c) = problem.m(rows[static_cast<std::size_t>(r)], rows[static_cast<std::size_t>(c)]);
    }
    z.setZero();
    if (k > 0) {
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
      if (!(lu.rcond() > options_.singular_tolerance))
        return make_lcp_result(problem, LcpStatus::numerical_failure, z, iteration);
      Eigen::VectorXd za = lu.solve(rhs);
      za += lu.solve(rhs - a * za);  // one step of iterative refinement
      for (Eigen::Index r = 0; r < k; ++r)
        z(rows[static_cast<std::size_t>(r)]) = za(r);
    }
    const Eigen::VectorXd w = problem.m * z + problem.q;
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const char now = z(i) > w(i);
      changed = changed || now != active[static_cast<std::size_t>(i)];
      active[static_cast<std::size_t>(i)] = now;
    }
    if (!changed) {
      // Rows of A whose multiplier is zero but for round-off are set to zero exactly.
      LcpResult result = make_lcp_result(problem, LcpStatus::solved, z.cwiseMax(0.0), iteration);
      if (!result.z.allFinite() || !(result.residuals.worst_relative() <= options_.accuracy))
        result.status = LcpStatus::numerical_failure;
      return result;
    }
  }
  return make_lcp_result(problem, LcpStatus::iteration_limit, z, options_.max_iterations);
}

}  // namespace bimrock
