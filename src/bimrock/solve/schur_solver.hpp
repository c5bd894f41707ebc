#pragma once
/// @file Solves with the Schur complement S of a zone through the factor it was read from: after
/// SparseCholesky::analyze_last, the trailing block of the factor is a factor of S (L_PP L_PP^T
/// = S), so S needs no factorization of its own. The unknowns are those of
/// SparseCholesky::schur_complement (trailing_unknowns).
#include <bimrock/solve/sparse_cholesky.hpp>
#include <bimrock/solve/spd_solver.hpp>

namespace bimrock {

class SchurSolver final : public SpdSolver {
 public:
  /// `factor` (analyzed by analyze_last and factorized) must outlive this and stay as it is.
  SchurSolver(const SparseCholesky& factor, int level);

  [[nodiscard]] std::int64_t rows() const override { return rows_; }
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  [[nodiscard]] Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override;
  [[nodiscard]] std::int64_t factor_nonzeros() const override { return nonzeros_; }
  [[nodiscard]] const CholeskyWork& work() const override { return work_; }

 private:
  const SparseCholesky& factor_;
  int level_;
  std::int64_t rows_;
  std::int64_t nonzeros_;
  mutable CholeskyWork work_;
};

}  // namespace bimrock
