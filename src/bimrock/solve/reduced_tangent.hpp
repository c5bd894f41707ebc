#pragma once
/// @file The active-set equations of the increment LCP w = q + (N - C K^-1 Phi) z solved on the
/// sparse reduced tangent instead of the dense active block, for symmetric LCPs (associated
/// flow). With the rows A active (w_A = 0, z = 0 elsewhere) and x = K^-1 Phi_A z_A the plastic
/// displacements (split_lcp_equations.hpp):
///
///   (K - Phi_A N_AA^-1 C_A) x = -Phi_A N_AA^-1 q_A,   z_A = N_AA^-1 (C_A x - q_A),
///   w = q + N z - C x.
///
/// N is block diagonal by yield point, so N_AA^-1 is local and the reduced tangent has the
/// pattern of K (a yield point couples only the blocks its interface joins): one symbolic
/// analysis serves every active set, and each costs one numeric factorization of K's size,
/// whatever |A| is. The dense route costs |A|^3 / 3 and a back-solve per new active row: this one
/// wins when many rows are active. Cholesky needs the tangent symmetric (associated flow, C =
/// Phi^T and N symmetric) and positive definite: it is not at a mechanism, and then the
/// equations report themselves singular, with the mechanism's multipliers as a Farkas
/// certificate when the tangent's kernel gives one (else the caller goes back to the dense
/// route). The result is measured with K's own factor (x = K^-1 Phi z, one back-solve),
/// independently of the tangent, unless the caller asks only for the tangent's own. An active set
/// whose tangent differs from the factored one in a few groups is solved through that factor
/// instead (Woodbury, see update_from_kept).
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <bimrock/solve/sparse_cholesky.hpp>
#include <bimrock/solve/split_lcp_equations.hpp>

namespace bimrock {

using SparseColumn = Eigen::SparseVector<double, Eigen::ColMajor, std::int64_t>;

/// One group's part of a reduced tangent, Phi_g N_gg^-1 C_g: the columns of Phi of its active
/// rows and their (damped) N_gg. A kept factor is described by its terms, so that a later LCP,
/// whose rows are numbered otherwise, can tell how its own tangent differs from it.
struct TangentTerm {
  Eigen::Index group = 0;  ///< SplitLcp::group: the same yield point in every LCP
  std::vector<int> modes;  ///< each active row's place among the rows of its group
  std::vector<SparseColumn> phi;
  Eigen::MatrixXd n_local;
};

/// The factor of the reduced tangent, kept from one LCP to the next: its symbolic analysis
/// serves every active set, and its numeric factor the next LCPs whose tangents are the same
/// or differ from it in a few groups (each candidate round starts from the active set the
/// last one ended with, each increment from the last increment's).
struct TangentFactor {
  SparseCholesky cholesky;
  /// The last tangent formed (lower triangle): K's pattern, its values overwritten each time.
  CholmodMatrix matrix;
  /// The tangent `cholesky` holds the factor of, as K minus these terms (empty: none).
  std::optional<std::vector<TangentTerm>> terms;
  /// S^-1 phi of the rows updates used, by group and mode (with the phi they were solved
  /// for), kept while the factor is: the rows an update changes are much the same from one
  /// active-set iteration to the next.
  struct Column {
    SparseColumn phi;
    Eigen::VectorXd solved;
  };
  std::map<std::pair<Eigen::Index, int>, Column> columns;
};

/// How much the tangent of a solve may differ from the one whose factor is kept and still be
/// solved through it (a low-rank update) instead of factorized: rows whose terms differ, and
/// back-solves for the columns not kept from earlier updates. Negative: chosen from the
/// factor's memory and its cost against a back-solve's.
struct TangentUpdateLimits {
  Eigen::Index rows = -1;
  double new_columns = -1.0;
};

class ReducedTangentEquations final : public SplitLcpEquations {
 public:
  /// @param k the factor of K (to measure results)
  /// @param tangent analyzed here when its pattern is not the tangent's
  ReducedTangentEquations(const SplitLcp& lcp, const SpdSolver& k, TangentFactor& tangent,
                          TangentUpdateLimits limits = {});

  [[nodiscard]] bool symmetric() const override { return true; }
  using ActiveSetEquations::solve;
  /// The damping scales N_rr (it is added to N_AA: the tangent keeps K's pattern).
  /// Check::from_solve takes w = q + N z - C x with the tangent's own x (no back-solve with K,
  /// no refinement, and an update through the kept factor is not checked).
  [[nodiscard]] Solution solve(const std::vector<Eigen::Index>& active, const Damping& damping,
                               Check check) override;
  /// M_rr = N_rr - phi_r . K^-1 phi_r <= N_rr.
  [[nodiscard]] double diagonal_bound(Eigen::Index row) const override { return n_diagonal_(row); }

  /// Numeric factorizations of the tangent so far, the solves that reused a factor as it was,
  /// and those that reused it through a low-rank update (Woodbury).
  [[nodiscard]] int factorizations() const override { return factorizations_; }
  [[nodiscard]] int reused_factors() const { return reused_; }
  [[nodiscard]] int updated_factors() const { return updated_; }

 private:
  struct Update;
  /// The solve of the new tangent through the kept factor of another one when they differ in
  /// few groups (S_new = S_kept - P D P^T, Woodbury), or nothing if they differ in too many or
  /// the new one is not positive definite.
  [[nodiscard]] std::optional<Update> update_from_kept(const std::vector<TangentTerm>& terms);
  [[nodiscard]] Eigen::VectorXd solve_tangent(const Eigen::VectorXd& rhs,
                                              const Update* update) const;
  /// solve(), through a low-rank update of the kept factor if `may_update`; nothing if that
  /// was not accurate enough.
  [[nodiscard]] std::optional<Solution> solve_on(const std::vector<Eigen::Index>& active,
                                                 const Damping& damping, bool may_update,
                                                 Check check);
  /// K - Phi_A N_AA^-1 C_A (lower triangle), formed in TangentFactor::matrix.
  [[nodiscard]] const CholmodMatrix& form_tangent(const std::vector<Eigen::Index>& active,
                                                  const std::vector<Local>& locals);
  /// Factorizes `tangent`; false if it is not positive definite.
  [[nodiscard]] bool factorize(const CholmodMatrix& tangent);
  /// The place of `row` among the rows of its group.
  [[nodiscard]] int mode(Eigen::Index row) const;
  /// The mechanism's multipliers where `tangent` is singular, as a Farkas certificate checked
  /// on the LCP; empty if they are not one.
  [[nodiscard]] Eigen::VectorXd mechanism(const CholmodMatrix& tangent,
                                          const std::vector<Eigen::Index>& active,
                                          const std::vector<Local>& locals);

  TangentFactor& tangent_;
  Eigen::VectorXd n_diagonal_;
  TangentUpdateLimits limits_;
  int factorizations_ = 0;
  int reused_ = 0;
  int updated_ = 0;
};

}  // namespace bimrock
