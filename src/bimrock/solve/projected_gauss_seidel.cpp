#include <bimrock/solve/projected_gauss_seidel.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bimrock {

LcpResult ProjectedGaussSeidel::solve(const LcpProblem& problem,
                                      const Eigen::VectorXd* warm_start) {
  check_lcp(problem);
  const Eigen::Index n = problem.size();
  if (!(options_.relaxation > 0.0 && options_.relaxation < 2.0)) {
    throw std::invalid_argument("projected Gauss-Seidel: relaxation must lie in (0, 2)");
  }
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  if (warm_start != nullptr) {
    if (warm_start->size() != n) {
      throw std::invalid_argument("projected Gauss-Seidel: warm start of the wrong size");
    }
    z = warm_start->cwiseMax(0.0);
  }
  if (n > 0 && !(problem.m.diagonal().array() > 0.0).all()) {
    return make_lcp_result(problem, LcpStatus::numerical_failure, z, 0);
  }
  // Rows are read one at a time: store them contiguously.
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m = problem.m;
  const double omega = options_.relaxation;
  bool measure_now = true;  // the start may solve it already
  for (int sweep = 0;; ++sweep) {
    if (measure_now || sweep == options_.max_iterations) {
      LcpResult result = make_lcp_result(problem, LcpStatus::solved, z, sweep);
      if (result.residuals.worst_relative() <= options_.tolerance)
        return result;
      if (sweep == options_.max_iterations) {
        result.status = LcpStatus::iteration_limit;
        return result;
      }
    }
    double change = 0.0;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double w_i = m.row(i).dot(z) + problem.q(i);
      const double z_i = std::max(0.0, z(i) - omega * w_i / m(i, i));
      change = std::max(change, std::abs(z_i - z(i)));
      z(i) = z_i;
    }
    if (!z.allFinite())
      return make_lcp_result(problem, LcpStatus::numerical_failure, z, sweep + 1);
    // Measuring costs as much as a sweep: do it when the iterates have settled, and now and
    // then (a slowly converging iteration takes small steps long before it has converged).
    measure_now = change <= options_.tolerance * z.cwiseAbs().maxCoeff() || sweep % 16 == 15;
  }
}

}  // namespace bimrock
