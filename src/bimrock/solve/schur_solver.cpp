#include <bimrock/solve/schur_solver.hpp>

#include <chrono>
#include <stdexcept>

namespace bimrock {

SchurSolver::SchurSolver(const SparseCholesky& factor, int level)
    : factor_(factor),
      level_(level),
      rows_(static_cast<std::int64_t>(factor.trailing_unknowns(level).size())),
      nonzeros_(factor.trailing_nonzeros(level)) {
  if (rows_ == 0)
    throw std::logic_error("SchurSolver: the factor has no zone of that level");
}

Eigen::MatrixXd SchurSolver::solve(const Eigen::MatrixXd& b) const {
  const auto start = std::chrono::steady_clock::now();
  Eigen::MatrixXd x = factor_.solve_trailing(b, level_);
  work_.solved_columns += b.cols();
  work_.solve_seconds +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return x;
}

Eigen::VectorXd SchurSolver::solve(const Eigen::VectorXd& b) const {
  return solve(Eigen::MatrixXd(b)).col(0);
}

}  // namespace bimrock
