#include <bimrock/solve/working_set_lcp.hpp>

#include <algorithm>
#include <iterator>

namespace bimrock {

LcpResult solve_on_working_set(LcpColumns& problem, const std::vector<Eigen::Index>& initial,
                               Lemke& lemke, const WorkingSetOptions& options) {
  const Eigen::Index n = problem.size();
  const Eigen::VectorXd& q = problem.q();
  if ((q.array() >= 0.0).all())  // z = 0 solves it (also for n = 0)
    return make_lcp_result(q, {}, Eigen::MatrixXd(n, 0), LcpStatus::solved,
                           Eigen::VectorXd::Zero(n), 0);
  std::vector<char> in_set(static_cast<std::size_t>(n), 0);
  for (Eigen::Index i : initial)
    in_set[static_cast<std::size_t>(i)] = 1;
  for (Eigen::Index i = 0; i < n; ++i)
    if (q(i) < 0.0)
      in_set[static_cast<std::size_t>(i)] = 1;

  std::vector<Eigen::Index> set;  // W, in increasing order
  Eigen::MatrixXd columns(n, 0);  // the columns of M on W, in the order of `set`
  LcpResult result;
  result.z = Eigen::VectorXd::Zero(n);
  int pivots = 0;
  for (int round = 1; round <= options.max_rounds; ++round) {
    std::vector<Eigen::Index> added;
    for (Eigen::Index i = 0; i < n; ++i)
      if (in_set[static_cast<std::size_t>(i)] && !std::binary_search(set.begin(), set.end(), i))
        added.push_back(i);
    if (added.empty())
      break;  // nothing new to add and still not solved: give up
    // Merge the new rows and their columns into W, keeping W sorted.
    const Eigen::MatrixXd fresh = problem.columns(added);
    std::vector<Eigen::Index> merged;
    std::merge(set.begin(), set.end(), added.begin(), added.end(), std::back_inserter(merged));
    Eigen::MatrixXd merged_columns(n, static_cast<Eigen::Index>(merged.size()));
    for (std::size_t k = 0, a = 0, b = 0; k < merged.size(); ++k) {
      const bool old = a < set.size() && set[a] == merged[k];
      if (old)
        merged_columns.col(static_cast<Eigen::Index>(k)) =
            columns.col(static_cast<Eigen::Index>(a++));
      else
        merged_columns.col(static_cast<Eigen::Index>(k)) =
            fresh.col(static_cast<Eigen::Index>(b++));
    }
    set = std::move(merged);
    columns = std::move(merged_columns);

    const auto k = static_cast<Eigen::Index>(set.size());
    LcpProblem sub{Eigen::MatrixXd(k, k), Eigen::VectorXd(k)};
    for (Eigen::Index r = 0; r < k; ++r) {
      sub.q(r) = q(set[static_cast<std::size_t>(r)]);
      sub.m.row(r) = columns.row(set[static_cast<std::size_t>(r)]);
    }
    const LcpResult local = lemke.solve(sub);
    pivots += local.steps;
    if (local.status == LcpStatus::no_solution && problem.symmetric() && local.ray.size() == k) {
      // The sub-LCP's ray r_W, extended by zeros, may certify the whole LCP.
      Eigen::VectorXd ray = certified_ray(q, set, columns, local.ray);
      if (ray.size() == n) {
        result = make_lcp_result(q, {}, Eigen::MatrixXd(n, 0), LcpStatus::no_solution,
                                 Eigen::VectorXd::Zero(n), pivots);
        result.ray = std::move(ray);
        return result;
      }
    }
    if (local.status != LcpStatus::solved) {
      result.status =
          local.status == LcpStatus::no_solution ? LcpStatus::numerical_failure : local.status;
      result.steps = pivots;
      return result;
    }
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    for (Eigen::Index r = 0; r < k; ++r)
      z(set[static_cast<std::size_t>(r)]) = local.z(r);
    result = make_lcp_result(q, set, columns, LcpStatus::solved, z, pivots);
    if (result.z.allFinite() && result.residuals.worst_relative() <= options.accuracy)
      return result;
    // Rows off W that the solution violates join W.
    for (Eigen::Index i = 0; i < n; ++i)
      if (result.w(i) < 0.0)
        in_set[static_cast<std::size_t>(i)] = 1;
  }
  result.status = LcpStatus::iteration_limit;
  result.steps = pivots;
  return result;
}

}  // namespace bimrock
