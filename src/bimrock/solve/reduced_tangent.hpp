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
/// instead (Woodbury, tangent_factor.hpp).
#include <map>
#include <optional>
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <bimrock/solve/sparse_cholesky.hpp>
#include <bimrock/solve/split_lcp_equations.hpp>
#include <bimrock/solve/tangent_factor.hpp>

namespace bimrock {

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

  /// The solve of the tangent of the rows `active` (undamped), through the kept factor as it is
  /// or updated, else factorized into it; nothing where that tangent is not positive definite.
  /// A preconditioner of a nearby tangent (unsymmetric_tangent.hpp); it holds until the kept
  /// factor next changes.
  [[nodiscard]] std::optional<LinearSolve> tangent_solve(const std::vector<Eigen::Index>& active);

  /// Numeric factorizations of the tangent so far, the solves that reused a factor as it was,
  /// and those that reused it through a low-rank update (Woodbury).
  [[nodiscard]] int factorizations() const override { return factorizations_; }
  [[nodiscard]] int reused_factors() const { return reused_; }
  [[nodiscard]] int updated_factors() const { return updated_; }

 private:
  /// solve(), through a low-rank update of the kept factor if `may_update`; nothing if that
  /// was not accurate enough.
  [[nodiscard]] std::optional<Solution> solve_on(const std::vector<Eigen::Index>& active,
                                                 const Damping& damping, bool may_update,
                                                 Check check);
  /// Makes the kept factor serve the tangent of the rows `active` (their `locals`): as it is or
  /// through a low-rank update (`update`, if `may_update` and one serves), else factorized anew;
  /// false where that tangent is not positive definite (it is then in TangentFactor::matrix).
  [[nodiscard]] bool hold_tangent(const std::vector<Eigen::Index>& active,
                                  const std::vector<Local>& locals, bool may_update,
                                  std::optional<TangentUpdate>& update);
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
