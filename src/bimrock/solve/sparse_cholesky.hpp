#pragma once
/// @file Sparse Cholesky factorization of the stiffness K with CHOLMOD (64-bit indices).
/// Pattern first (analyze: fill-reducing ordering, symbolic factor), values second (factorize),
/// so one factor object serves every load increment of an analysis.
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace bimrock {

using CholmodMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, std::int64_t>;

/// The work one factor object has done: where a solver's time goes (the bench reports it).
struct CholeskyWork {
  int factorizations = 0;
  std::int64_t solved_columns = 0;  ///< right-hand sides, over all solves
  double factorize_seconds = 0.0;
  double solve_seconds = 0.0;
};

class SparseCholesky {
 public:
  SparseCholesky();
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Symbolic analysis of the pattern of `lower` (the lower triangle of a symmetric matrix).
  /// With block_size > 1 the fill-reducing ordering is computed on the graph of dense
  /// block_size x block_size blocks (the 6 unknowns of a block move together): 36 times fewer
  /// entries to order for the same permutation quality.
  void analyze(const CholmodMatrix& lower, int block_size = 1);

  /// Symbolic analysis that orders the blocks flagged in `last` (one flag per block of
  /// block_size unknowns) after all the others, so that their Schur complement is the trailing
  /// part of the factor (schur_complement()). The others are ordered as analyze() orders a whole
  /// matrix; the flagged ones coupled to no other come first among them, those coupled to one
  /// at the very end (the Schur complement is dense on them). The factor is supernodal.
  void analyze_last(const CholmodMatrix& lower, int block_size, const std::vector<char>& last);

  /// After analyze_last() and a successful factorize(): with P the flagged unknowns and E the
  /// others, S = K_PP - K_PE K_EE^-1 K_EP = L_PP L_PP^T (lower triangle), its rows and columns in
  /// the order of trailing_unknowns() (each block's unknowns together, as in K).
  [[nodiscard]] CholmodMatrix schur_complement(const CholmodMatrix& lower) const;
  /// The unknowns of K in the order of schur_complement()'s rows (empty unless analyze_last()).
  [[nodiscard]] const std::vector<std::int64_t>& trailing_unknowns() const { return trailing_; }

  /// Numeric factorization; false when the matrix is not positive definite, in which case
  /// failed_column() names the original column where the factorization broke down.
  bool factorize(const CholmodMatrix& lower);

  [[nodiscard]] bool factorized() const { return factorized_; }
  /// Non-zeros of the (lower) matrix whose pattern was analyzed (0 before analyze): a matrix
  /// with another pattern must be analyzed anew before it is factorized.
  [[nodiscard]] std::int64_t analyzed_nonzeros() const { return analyzed_nonzeros_; }
  [[nodiscard]] std::int64_t failed_column() const { return failed_column_; }
  [[nodiscard]] std::int64_t rows() const { return n_; }
  /// Non-zeros of the factor L (a measure of its memory: 8 bytes each plus indices).
  [[nodiscard]] std::int64_t factor_nonzeros() const;
  /// CHOLMOD chose a supernodal factor (else simplicial: small or very sparse factors).
  [[nodiscard]] bool supernodal() const;
  /// Floating-point operations of one numeric factorization (CHOLMOD's count at analysis; 0
  /// before analyze). A solve costs about 4 factor_nonzeros() per right-hand side.
  [[nodiscard]] double factor_flops() const { return factor_flops_; }

  /// x = K^-1 b for one or several right-hand sides. After analyze_last(), a b that is zero
  /// outside the flagged blocks (a load on the zone) is solved forward on the trailing part of
  /// L only (L y = b leaves y = 0 on the leading unknowns): about half the work of a solve.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  [[nodiscard]] Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const;

  [[nodiscard]] const CholeskyWork& work() const { return work_; }

 private:
  struct Impl;
  /// Symbolic analysis with the given fill-reducing permutation; `exact`: kept exactly as
  /// given (not postordered) and the factor supernodal, as schur_complement() needs.
  void analyze_given(const CholmodMatrix& lower, const std::int64_t* perm, bool exact);
  /// solve(b) for a b that is zero on the leading unknowns of analyze_last()'s order.
  [[nodiscard]] Eigen::VectorXd solve_from_trailing(const Eigen::VectorXd& b) const;

  std::unique_ptr<Impl> impl_;
  std::int64_t n_ = 0;
  std::vector<std::int64_t> trailing_;
  std::vector<char> coupled_;  // per trailing unknown: its block is coupled to a leading one
  std::int64_t analyzed_nonzeros_ = 0;
  std::int64_t failed_column_ = -1;
  double factor_flops_ = 0.0;
  bool factorized_ = false;
  mutable CholeskyWork work_;
};

}  // namespace bimrock
