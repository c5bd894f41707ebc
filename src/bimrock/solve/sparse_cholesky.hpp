#pragma once
/// @file Sparse Cholesky factorization of the stiffness K with CHOLMOD (64-bit indices).
/// Pattern first (analyze: fill-reducing ordering, symbolic factor), values second (factorize),
/// so one factor object serves every load increment of an analysis. Its parts, one file each:
/// sparse_cholesky.cpp (analysis, factorization, solves), block_ordering.cpp, zone_ordering.cpp
/// and zone_schur_complement.cpp, over the state in sparse_cholesky_impl.hpp.
#include <cstdint>
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <bimrock/solve/spd_solver.hpp>

struct cholmod_sparse_struct;

namespace bimrock {

using CholmodMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, std::int64_t>;

class SparseCholesky final : public SpdSolver {
 public:
  SparseCholesky();
  ~SparseCholesky() override;
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  /// Symbolic analysis of the pattern of `lower` (the lower triangle of a symmetric matrix).
  /// With block_size > 1 the fill-reducing ordering is computed on the graph of dense
  /// block_size x block_size blocks (the 6 unknowns of a block move together): 36 times fewer
  /// entries to order for the same permutation quality.
  void analyze(const CholmodMatrix& lower, int block_size = 1);

  /// Symbolic analysis that orders the blocks by `level` (one per block of block_size unknowns:
  /// level 0 first, the highest last), so that for every l >= 1 the Schur complement onto the
  /// blocks of level >= l (the zone l) is the trailing part of the factor (schur_complement()).
  /// Within a level l >= 1, its blocks coupled to none of a lower level come first, those
  /// coupled to one (the zone l's boundary, on which its Schur complement is dense) at its end;
  /// within each such group the blocks keep the relative order analyze() gives the whole block
  /// graph (computed once per pattern and kept, so each new set of levels costs no ordering). The
  /// zones must nest: a block coupled to one two levels lower or more is a std::logic_error. The
  /// factor is supernodal.
  void analyze_last(const CholmodMatrix& lower, int block_size, const std::vector<char>& level);

  /// After analyze_last() and a successful factorize(): with P the unknowns of zone `level` and
  /// E the others, S = K_PP - K_PE K_EE^-1 K_EP = L_PP L_PP^T (lower triangle), its rows and
  /// columns in the order of trailing_unknowns(level) (each block's unknowns together, as in K).
  [[nodiscard]] CholmodMatrix schur_complement(const CholmodMatrix& lower, int level = 1) const;
  /// The unknowns of zone `level` in the order of schur_complement()'s rows (empty unless
  /// analyze_last() gave blocks that level).
  [[nodiscard]] std::vector<std::int64_t> trailing_unknowns(int level = 1) const;
  /// The highest level of analyze_last() (0 after analyze()).
  [[nodiscard]] int levels() const { return static_cast<int>(level_start_.size()) - 1; }

  /// Numeric factorization; false when the matrix is not positive definite, in which case
  /// failed_column() names the original column where the factorization broke down. The matrix
  /// must be compressed and have the analyzed pattern, else it is a std::logic_error (CHOLMOD
  /// itself does not check).
  bool factorize(const CholmodMatrix& lower);

  [[nodiscard]] bool factorized() const { return factorized_; }
  /// Non-zeros of the (lower) matrix whose pattern was analyzed (0 before analyze): a matrix
  /// with another pattern must be analyzed anew before it is factorized.
  [[nodiscard]] std::int64_t analyzed_nonzeros() const { return analyzed_nonzeros_; }
  [[nodiscard]] std::int64_t failed_column() const { return failed_column_; }
  [[nodiscard]] std::int64_t rows() const override { return n_; }
  /// Non-zeros of the factor L (a measure of its memory: 8 bytes each plus indices).
  [[nodiscard]] std::int64_t factor_nonzeros() const override;
  /// CHOLMOD chose a supernodal factor (else simplicial: small or very sparse factors).
  [[nodiscard]] bool supernodal() const;
  /// Floating-point operations of one numeric factorization (CHOLMOD's count at analysis; 0
  /// before analyze). A solve costs about 4 factor_nonzeros() per right-hand side.
  [[nodiscard]] double factor_flops() const { return factor_flops_; }

  /// x = K^-1 b for one or several right-hand sides. A single b whose entries are zero on the
  /// first quarter or more of the factor's order (after analyze_last(), a load on a zone) is
  /// solved forward from its first non-zero only (L y = b leaves y = 0 before it): up to half
  /// the work of a solve.
  [[nodiscard]] Eigen::VectorXd solve(const Eigen::VectorXd& b) const override;
  [[nodiscard]] Eigen::MatrixXd solve(const Eigen::MatrixXd& b) const override;

  /// After analyze_last() and a successful factorize(): x = S^-1 b for the Schur complement S of
  /// zone `level` (schur_complement()), through the trailing block of the factor (L_PP L_PP^T =
  /// S), b and x in the order of trailing_unknowns(level). Not counted in work().
  [[nodiscard]] Eigen::MatrixXd solve_trailing(const Eigen::MatrixXd& b, int level) const;
  /// Non-zeros of that trailing block of the factor.
  [[nodiscard]] std::int64_t trailing_nonzeros(int level) const;

  [[nodiscard]] const CholeskyWork& work() const override { return work_; }

 private:
  struct Impl;
  /// Symbolic analysis with the given fill-reducing permutation (null: the natural order);
  /// `exact`: kept exactly as given (not postordered) and the factor supernodal, as
  /// schur_complement() needs.
  void analyze_given(const cholmod_sparse_struct& matrix, const std::int64_t* perm, bool exact);
  /// What every analysis ends with: the factor checked, its size and flops recorded.
  void finish_analysis(const CholmodMatrix& lower);
  /// The fill-reducing order of a block graph (CHOLMOD's default strategy), kept for the last
  /// pattern it was computed for.
  const std::vector<std::int64_t>& block_order(const CholmodMatrix& pattern);
  /// tril(P lower P^T) for the order `perm` (the factor's, or analyze_last()'s), and the scatter
  /// of `lower`'s entries into it (see Impl).
  void permute_into_order(const CholmodMatrix& lower, const std::int64_t* perm);
  /// solve(b) for a b whose first `first` entries in the factor's order are zero.
  [[nodiscard]] Eigen::VectorXd solve_from(const Eigen::VectorXd& b, std::int64_t first) const;

  std::unique_ptr<Impl> impl_;
  std::int64_t n_ = 0;
  std::vector<std::int64_t> order_;  // after analyze_last(): the unknowns in the factor's order
  std::vector<std::int64_t> block_order_;  // block_order()'s, and the fingerprint of its graph
  std::uint64_t block_order_key_ = 0;
  // Per level l >= 1 of analyze_last(), in the factor's order: where its blocks start, and where
  // those coupled to a lower level start (they end where the next level starts); level 0 starts
  // at 0. Empty after analyze().
  std::vector<std::int64_t> level_start_;
  std::vector<std::int64_t> boundary_start_;
  std::int64_t analyzed_nonzeros_ = 0;
  std::int64_t failed_column_ = -1;
  double factor_flops_ = 0.0;
  bool factorized_ = false;
  mutable CholeskyWork work_;
};

}  // namespace bimrock
