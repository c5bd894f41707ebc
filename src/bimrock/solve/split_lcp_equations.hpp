#pragma once
/// @file What the active-set equations on a sparse reduced tangent share, whether the tangent is
/// symmetric (reduced_tangent.hpp: Cholesky) or not (unsymmetric_tangent.hpp: LU). With the
/// rows A active and x = S^-1 Phi_A z_A the plastic displacements:
///
///   (S - Phi_A N_AA^-1 C_A) x = -Phi_A N_AA^-1 q_A,   z_A = N_AA^-1 (C_A x - q_A),
///   w = q + N z - C x.
///
/// N is block diagonal by yield point, so N_AA^-1 is one small inverse per group of active
/// rows (Local); the two halves of a solve through the tangent (its load, then z_A from its x),
/// the residual w with its scale, and the measure of a result with S's own factor are the same
/// for both.
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>  // CholmodMatrix
#include <bimrock/solve/spd_solver.hpp>

namespace bimrock {

/// x = A^-1 b for some tangent A (a factor's solve, or an iterative one).
using LinearSolve = std::function<Eigen::VectorXd(const Eigen::VectorXd&)>;

/// The sparse parts of the increment LCP (eqs. 24, 28), all in the unknowns of S (K, or K
/// condensed) and the LCP's rows. The rows of a group (the modes of one yield point) are
/// consecutive.
struct SplitLcp {
  const CholmodMatrix* k_lower = nullptr;  ///< n x n, lower triangle of S
  const CholmodMatrix* c = nullptr;        ///< m x n
  const CholmodMatrix* phi = nullptr;      ///< n x m
  const CholmodMatrix* n = nullptr;        ///< m x m, block diagonal by group
  Eigen::VectorXd q;                       ///< m
  std::vector<Eigen::Index> group;         ///< per row: its group
  std::vector<int> group_rank;             ///< per row: independent rows of its group at most
};

/// Appends the triplets of Phi_R L C_R (n x n) for the rows R = rows[0 .. L.rows()) of one
/// group and a local matrix L: a plastic part of a reduced tangent. It couples only the unknowns
/// of the blocks the group's yield point joins, so a tangent keeps S's pattern. `c_transposed`
/// holds the rows of C as columns.
void add_plastic_coupling(const CholmodMatrix& phi, const CholmodMatrix& c_transposed,
                          const Eigen::Index* rows, const Eigen::MatrixXd& local,
                          std::vector<Eigen::Triplet<double, std::int64_t>>& out);

class SplitLcpEquations : public ActiveSetEquations {
 public:
  [[nodiscard]] Eigen::Index size() const override { return lcp_.q.size(); }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return lcp_.q; }
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override {
    return lcp_.group[static_cast<std::size_t>(row)];
  }
  [[nodiscard]] int group_rank(Eigen::Index row) const override {
    return lcp_.group_rank[static_cast<std::size_t>(row)];
  }
  /// z with w = M z + q measured with S's factor (x = S^-1 Phi z).
  [[nodiscard]] LcpResult result(LcpStatus status, Eigen::VectorXd z, int steps) override;

 protected:
  /// @param s the factor of S (to measure results)
  SplitLcpEquations(const SplitLcp& lcp, const SpdSolver& s);

  /// The active rows of one group: N_gg of them (damped), its inverse, and where they start in
  /// `active`.
  struct Local {
    std::size_t first = 0;
    Eigen::MatrixXd block;
    Eigen::MatrixXd inverse;
  };
  /// A solution with z = 0, not yet regular; with no active rows, the whole answer (x = 0: no
  /// factorization, w = q, regular).
  [[nodiscard]] Solution start(const std::vector<Eigen::Index>& active) const;
  /// One Local per group of active rows (consecutive in `active`), N_rr of each scaled by
  /// 1 + damping.factor(r); nothing where a block is singular (e.g. both slip modes of a
  /// frictionless joint point): left to the dense route.
  [[nodiscard]] std::optional<std::vector<Local>> locals(const std::vector<Eigen::Index>& active,
                                                         const Damping& damping) const;
  /// C_R x on the rows of one Local (the rates of their yield functions).
  [[nodiscard]] Eigen::VectorXd strain(const std::vector<Eigen::Index>& active, const Local& l,
                                       const Eigen::VectorXd& x) const;
  /// The tangent's load -Phi_A N_AA^-1 v_A, with v_A split by Local into `v_locals`.
  [[nodiscard]] Eigen::VectorXd plastic_load(const std::vector<Eigen::Index>& active,
                                             const std::vector<Local>& locals,
                                             const Eigen::VectorXd& v,
                                             std::vector<Eigen::VectorXd>& v_locals) const;
  /// z_A += N_AA^-1 (C_A x - v_A), from the tangent's x.
  void add_multipliers(const std::vector<Eigen::Index>& active, const std::vector<Local>& locals,
                       const Eigen::VectorXd& x, const std::vector<Eigen::VectorXd>& v_locals,
                       Eigen::VectorXd& z) const;
  /// The damping's diagonal D: damping.factor times N_rr on the active rows, 0 elsewhere.
  [[nodiscard]] Eigen::VectorXd damping_terms(const std::vector<Eigen::Index>& active,
                                              const Damping& damping) const;
  /// A solve must meet the active rows' equations to this relative residual (the LCP asks for
  /// 1e-9), else it is refined once.
  static constexpr double kSolveAccuracy = 1e-10;
  /// The active rows' equations solved through a tangent (`tangent_solve`: x from the tangent's
  /// load), z_A added to out.z. With Check::from_solve, w is the tangent's own (out.measured
  /// false) and the return is 0; else out is measured with S's factor, refined once on the
  /// LCP's own residual where it misses kSolveAccuracy, and the worst relative residual of the
  /// active rows is returned.
  double solve_through(const std::vector<Eigen::Index>& active, const std::vector<Local>& locals,
                       const Damping& damping, Check check, const LinearSolve& tangent_solve,
                       Solution& out) const;
  /// Measures out.z with S's factor (x = S^-1 Phi z, then out.w and out.w_scale) and returns
  /// the worst relative residual of the active rows' equations (M_AA + D) z_A + q_A - D center_A
  /// (infinity for a NaN).
  double measure_active(const std::vector<Eigen::Index>& active, const Eigen::VectorXd& d,
                        const Damping& damping, Solution& out, Eigen::VectorXd& x) const;
  /// w = q + N z - C x and its scale |q| + |N| |z| + |C| |x|, row by row in one pass.
  void residual(const Eigen::VectorXd& z, const Eigen::VectorXd& x, Eigen::VectorXd& w,
                Eigen::VectorXd& scale) const;

  const SplitLcp& lcp_;
  const SpdSolver& s_;
  CholmodMatrix c_transposed_;  // n x m: the rows of C as columns
  CholmodMatrix n_transposed_;  // m x m: the rows of N as columns
};

}  // namespace bimrock
