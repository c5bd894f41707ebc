#pragma once
/// @file Solves with a symmetric positive definite matrix that is factorized already: K's
/// factor (SparseCholesky), or the trailing block of one, which is a factor of the Schur
/// complement of a zone (SchurSolver). The LCP's solvers take either.
#include <cstdint>

#include <Eigen/Core>

namespace bimrock {

/// The work one solver has done: where a solver's time goes (the bench reports it).
struct CholeskyWork {
  int factorizations = 0;
  std::int64_t solved_columns = 0;  ///< right-hand sides, over all solves
  double factorize_seconds = 0.0;
  double solve_seconds = 0.0;

  CholeskyWork& operator+=(const CholeskyWork& w) {
    factorizations += w.factorizations;
    solved_columns += w.solved_columns;
    factorize_seconds += w.factorize_seconds;
    solve_seconds += w.solve_seconds;
    return *this;
  }
};

class SpdSolver {
 public:
  virtual ~SpdSolver() = default;
  [[nodiscard]] virtual std::int64_t rows() const = 0;
  /// x = A^-1 b for one or several right-hand sides.
  [[nodiscard]] virtual Eigen::VectorXd solve(const Eigen::VectorXd& b) const = 0;
  [[nodiscard]] virtual Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const = 0;
  /// Non-zeros of the factor the solves go through (a solve costs about 4 per right-hand side).
  [[nodiscard]] virtual std::int64_t factor_nonzeros() const = 0;
  [[nodiscard]] virtual const CholeskyWork& work() const = 0;

 protected:
  SpdSolver() = default;
  SpdSolver(const SpdSolver&) = default;
  SpdSolver& operator=(const SpdSolver&) = default;
};

}  // namespace bimrock
