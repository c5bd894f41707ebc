#pragma once
/// @file The active-set equations of a non-symmetric increment LCP (non-associated flow: C is
/// not Phi^T, N not symmetric) solved on the sparse reduced tangent, as reduced_tangent.hpp
/// does for symmetric ones. With the rows A active and x = S^-1 Phi_A z_A:
///
///   (S - Phi_A N_AA^-1 C_A) x = -Phi_A N_AA^-1 q_A,   z_A = N_AA^-1 (C_A x - q_A).
///
/// The tangent keeps the pattern of S (N_AA is local to each yield point) but not its symmetry,
/// so it is factorized by sparse LU (UMFPACK), one factorization per active set; without
/// symmetry there is no positive definiteness to test and no low-rank update whose inertia
/// tells it, so neither the kept-factor updates nor the kernel search of the symmetric route
/// apply. Each result is measured with S's own factor (x = S^-1 Phi z), refined once where the
/// active rows miss their equations, and called singular where they still miss them: the
/// dense route and the complete method then decide the LCP.
///
/// Given a preconditioner, the solve of a symmetric tangent of the same active rows (the
/// associated form's, whose rows follow the flow: the splitting's inner LCPs keep its factor,
/// reduced_tangent.hpp), the tangent is first solved by GMRES on it, which costs a few tens of
/// back-solves where the LU costs several Cholesky factorizations; the LU takes over where
/// GMRES does not converge or its result misses the accuracy.
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <bimrock/solve/split_lcp_equations.hpp>

namespace bimrock {

class UnsymmetricTangentEquations final : public SplitLcpEquations {
 public:
  /// The solve of a symmetric tangent near this one for the active rows given, or nothing.
  using Preconditioner =
      std::function<std::optional<LinearSolve>(const std::vector<Eigen::Index>& active)>;
  /// @param s the factor of the stiffness the LCP is written on (K, or K condensed)
  UnsymmetricTangentEquations(const SplitLcp& lcp, const SpdSolver& s,
                              Preconditioner preconditioner = {});
  ~UnsymmetricTangentEquations() override;
  UnsymmetricTangentEquations(const UnsymmetricTangentEquations&) = delete;
  UnsymmetricTangentEquations& operator=(const UnsymmetricTangentEquations&) = delete;

  using ActiveSetEquations::solve;
  [[nodiscard]] Solution solve(const std::vector<Eigen::Index>& active, const Damping& damping,
                               Check check) override;

  /// Numeric LU factorizations of the tangent so far, and the active sets solved by GMRES
  /// without one.
  [[nodiscard]] int factorizations() const override { return factorizations_; }
  [[nodiscard]] int iterative_solves() const { return iterative_solves_; }

 private:
  struct Lu;
  /// The active rows' equations solved by GMRES on the tangent in lu_, preconditioned by
  /// `preconditioner`, as solve() does: false (out untouched) where it does not converge, or the
  /// result misses the accuracy where it is measured.
  [[nodiscard]] bool solve_iteratively(const std::vector<Eigen::Index>& active,
                                       const std::vector<Local>& locals, const Damping& damping,
                                       Check check, const LinearSolve& preconditioner,
                                       Solution& out) const;

  CholmodMatrix s_full_;  // S, both triangles
  Preconditioner preconditioner_;
  std::unique_ptr<Lu> lu_;
  int factorizations_ = 0;
  int iterative_solves_ = 0;
};

}  // namespace bimrock
