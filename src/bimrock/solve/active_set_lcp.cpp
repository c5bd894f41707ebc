#include <bimrock/solve/active_set_lcp.hpp>

#include <set>
#include <stdexcept>
#include <vector>

#include <Eigen/LU>

namespace bimrock {

LcpResult ActiveSetLcp::solve(const LcpProblem& problem, const Eigen::VectorXd* warm_start) {
  check_lcp(problem);
  DenseLcpColumns columns(problem);
  return solve(columns, warm_start);
}

LcpResult ActiveSetLcp::solve(LcpColumns& problem, const Eigen::VectorXd* warm_start) {
  const Eigen::Index n = problem.size();
  const Eigen::VectorXd& q = problem.q();
  if ((q.array() >= 0.0).all())
    return make_lcp_result(q, {}, Eigen::MatrixXd(n, 0), LcpStatus::solved,
                           Eigen::VectorXd::Zero(n), 0);
  if (warm_start != nullptr && warm_start->size() != n)
    throw std::invalid_argument("active-set LCP: warm start of the wrong size");

  // The columns of M asked for so far: column slot[i] of `known` is column i of M. Only the
  // columns of rows that are active at some iteration are ever formed.
  std::vector<Eigen::Index> slot(static_cast<std::size_t>(n), -1);
  Eigen::MatrixXd known(n, 0);
  auto fetch = [&](const std::vector<Eigen::Index>& rows) {
    std::vector<Eigen::Index> missing;
    for (Eigen::Index i : rows)
      if (slot[static_cast<std::size_t>(i)] < 0)
        missing.push_back(i);
    if (missing.empty())
      return;
    const Eigen::MatrixXd fresh = problem.columns(missing);
    const Eigen::Index first = known.cols();
    known.conservativeResize(n, first + fresh.cols());
    known.rightCols(fresh.cols()) = fresh;
    for (std::size_t k = 0; k < missing.size(); ++k)
      slot[static_cast<std::size_t>(missing[k])] = first + static_cast<Eigen::Index>(k);
  };

  std::vector<char> active(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    active[static_cast<std::size_t>(i)] = warm_start ? (*warm_start)(i) > 0.0 : q(i) < 0.0;
  std::set<std::vector<char>> seen;  // an active set met twice is a cycle
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  std::vector<Eigen::Index> rows;
  Eigen::MatrixXd m_rows(n, 0);  // the columns of M on the active rows
  auto result = [&](LcpStatus status, int iteration) {
    return make_lcp_result(q, rows, m_rows, status, z, iteration);
  };
  for (int iteration = 1; iteration <= options_.max_iterations; ++iteration) {
    if (!seen.insert(active).second)
      return result(LcpStatus::iteration_limit, iteration);
    rows.clear();
    for (Eigen::Index i = 0; i < n; ++i)
      if (active[static_cast<std::size_t>(i)])
        rows.push_back(i);
    fetch(rows);
    const auto k = static_cast<Eigen::Index>(rows.size());
    m_rows.resize(n, k);
    for (Eigen::Index c = 0; c < k; ++c)
      m_rows.col(c) = known.col(slot[static_cast<std::size_t>(rows[static_cast<std::size_t>(c)])]);
    Eigen::MatrixXd a(k, k);
    Eigen::VectorXd rhs(k);
    for (Eigen::Index r = 0; r < k; ++r) {
      rhs(r) = -q(rows[static_cast<std::size_t>(r)]);
      a.row(r) = m_rows.row(rows[static_cast<std::size_t>(r)]);
    }
    z.setZero();
    Eigen::VectorXd za = Eigen::VectorXd::Zero(k);
    if (k > 0) {
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
      if (!(lu.rcond() > options_.singular_tolerance))
        return result(LcpStatus::numerical_failure, iteration);
      za = lu.solve(rhs);
      za += lu.solve(rhs - a * za);  // one step of iterative refinement
      for (Eigen::Index r = 0; r < k; ++r)
        z(rows[static_cast<std::size_t>(r)]) = za(r);
    }
    const Eigen::VectorXd w = m_rows * za + q;
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i) {
      const char now = z(i) > w(i);
      changed = changed || now != active[static_cast<std::size_t>(i)];
      active[static_cast<std::size_t>(i)] = now;
    }
    if (!changed) {
      // Rows of A whose multiplier is zero but for round-off are set to zero exactly.
      z = z.cwiseMax(0.0);
      LcpResult solved = result(LcpStatus::solved, iteration);
      if (!solved.z.allFinite() || !(solved.residuals.worst_relative() <= options_.accuracy))
        solved.status = LcpStatus::numerical_failure;
      return solved;
    }
  }
  return result(LcpStatus::iteration_limit, options_.max_iterations);
}

}  // namespace bimrock
