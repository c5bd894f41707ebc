#pragma once
/// @file Primal-dual active-set method for the LCP (Hintermueller, Ito and Kunisch 2002: a
/// semismooth Newton method on min(z, M z + q) = 0). Guess the active set A (rows with w = 0),
/// solve M_AA z_A = -q_A with z = 0 elsewhere, take as the new A the rows where z_i > w_i, and
/// repeat until A does not change: then z > 0 on A and w >= 0 elsewhere, a solution.
///
/// Each iteration costs one dense LU of the active block (|A|^3 / 3) and the columns of M of the
/// rows that became active for the first time, and the iterations are few
/// (typically 2 to 10, nearly independent of the size) where Lemke needs a pivot of O(n^2) per
/// row that enters: the fast route for increments with many active rows. It converges for
/// M-matrices and in practice for the positive semi-definite and near-P matrices of an
/// increment. Two safeguards for the increments near a collapse:
/// - at most group_rank rows of a group (the modes of one yield point, LcpColumns::group) are
///   active at once, those with the largest z_i - w_i: more would make the block singular;
/// - a singular active block of a symmetric M (associated flow) is tested as the mechanism of a
///   collapse: its kernel vector, if non-negative, M v <= 0 on every row and q . v < 0, is a
///   Farkas certificate that no solution exists (no_solution, with the vector as the ray).
/// Near a limit load the block rule can swap tens of rows at every iteration without end. A
/// symmetric M then goes on with projected Newton on the equivalent quadratic program (the same
/// equations of a free set, a projected line search that lowers the objective at every step,
/// and a proximal damping of singular blocks): it cannot cycle. A non-symmetric M goes on with
/// Murty's rule after a cycle. Otherwise it answers solved, or iteration_limit /
/// numerical_failure (a result that fails the check): the caller then falls back to Lemke.
/// The block rule is active_set_lcp.cpp; projected Newton, the equations of a problem given by
/// its columns and the certificate of a singular block have files of their own
/// (projected_newton.hpp, column_equations.hpp, kernel_certificate.hpp).
#include <functional>
#include <limits>
#include <utility>

#include <bimrock/solve/lcp.hpp>
#include <bimrock/solve/lcp_columns.hpp>

namespace bimrock {

struct ActiveSetOptions {
  /// Iterations of the block rule, and again as many of Murty's rule after a cycle.
  int max_iterations = 50;
  /// After a cycle of the block rule, go on with Murty's single-row rule (else give up), unless
  /// projected Newton takes over.
  bool murty_after_cycle = true;
  /// A symmetric problem goes on with the projected Newton iteration where the block rule does
  /// not converge: a cycle, a singular block that proves no collapse, or stall_iterations
  /// iterations in a row that have not lowered the count of violated rows below its best. One
  /// is enough: near a limit load a block rule that stalls seldom recovers, and projected Newton
  /// from its best iterate costs less than waiting for it.
  bool projected_newton = true;
  int stall_iterations = 1;
  /// The result must satisfy LcpResiduals::worst_relative() <= accuracy.
  double accuracy = 1e-9;
  /// Projected Newton steps after which each iterate is shown to the caller's Interrupt (0:
  /// never).
  int interrupt_after = 8;
  /// The active block is singular when the reciprocal condition estimate of its LU is below
  /// this (a mechanism, or a degenerate active set): left to Lemke.
  double singular_tolerance = 1e-13;
};

/// What the active-set iteration needs of an LCP, whatever represents M (its columns, or the
/// sparse parts of M = N - C K^-1 Phi): q, the groups of rows, and the equations of one active
/// set.
class ActiveSetEquations {
 public:
  virtual ~ActiveSetEquations() = default;
  [[nodiscard]] virtual Eigen::Index size() const = 0;
  [[nodiscard]] virtual const Eigen::VectorXd& q() const = 0;
  /// As LcpColumns::group and group_rank.
  [[nodiscard]] virtual Eigen::Index group(Eigen::Index row) const { return row; }
  [[nodiscard]] virtual int group_rank(Eigen::Index /*row*/) const { return 1; }
  /// M is symmetric (associated flow): the LCP is then the optimality condition of the convex
  /// quadratic program min 1/2 z.M z + q.z over z >= 0, which the iteration uses when the
  /// block rule stalls.
  [[nodiscard]] virtual bool symmetric() const { return false; }
  /// How a solve finds w: measured as M z + q independently of the solve (where M is in
  /// parts, one back-solve with K; refined once where it falls short of the accuracy), or from
  /// the solve's own equations (w_A = 0 by construction). The latter is enough to choose the
  /// next active set; a result is accepted, and an objective compared, only as measured.
  enum class Check { measured, from_solve };
  struct Solution {
    bool regular = false;     ///< false: M_AA is singular (or could not be factorized)
    bool measured = true;     ///< w was measured (Check::measured, or exact for this M)
    Eigen::VectorXd z;        ///< zero off the active rows, M_AA z_A = -q_A on them
    Eigen::VectorXd w;        ///< M z + q
    Eigen::VectorXd w_scale;  ///< the size of the terms that sum to each w_i (|M| |z| + |q|)
    Eigen::VectorXd ray;  ///< if singular: a Farkas certificate of no solution, if one was found
  };
  /// An upper bound of M_rr (infinity: none known). It bounds the objective at an iterate whose
  /// w was not measured (Check::from_solve).
  [[nodiscard]] virtual double diagonal_bound(Eigen::Index /*row*/) const {
    return std::numeric_limits<double>::infinity();
  }
  /// A proximal term D (z_A - center_A) added to the active rows' equations, with D diagonal:
  /// factor(r) >= 0 (one per active row; empty for none) times the row's own diagonal term (M_rr,
  /// or N_rr for a representation that keeps M in parts). It makes a singular active block
  /// regular, and the step from `center` still lowers the quadratic program's objective.
  struct Damping {
    Eigen::VectorXd factor;
    Eigen::VectorXd center;  ///< a z (all rows)
  };
  /// The solution of the equations of the active rows `active` (sorted):
  /// M_AA z_A + D (z_A - center_A) = -q_A, z = 0 elsewhere.
  [[nodiscard]] virtual Solution solve(const std::vector<Eigen::Index>& active,
                                       const Damping& damping, Check check) = 0;
  [[nodiscard]] Solution solve(const std::vector<Eigen::Index>& active, const Damping& damping) {
    return solve(active, damping, Check::measured);
  }
  [[nodiscard]] Solution solve(const std::vector<Eigen::Index>& active) {
    return solve(active, Damping{}, Check::measured);
  }
  /// Numeric factorizations of a sparse tangent so far (0 where there is none).
  [[nodiscard]] virtual int factorizations() const { return 0; }
  /// Any z with its w = M z + q and residuals on the whole LCP.
  [[nodiscard]] virtual LcpResult result(LcpStatus status, Eigen::VectorXd z, int steps) = 0;
};

class ActiveSetLcp final : public LcpSolver {
 public:
  /// Asked with each measured iterate of projected Newton from its interrupt_after-th step on,
  /// and with the last one where no step lowers the objective (before the solve fails), as
  /// z >= 0 with its w and residuals: true stops the solve, with LcpStatus::interrupted and that
  /// iterate. A caller that can learn from an iterate that its problem is incomplete (an
  /// increment's LCP lacking candidates) need not wait for a long solve to end.
  using Interrupt = std::function<bool(const LcpResult&)>;
  explicit ActiveSetLcp(ActiveSetOptions options = {}) : options_(std::move(options)) {}
  [[nodiscard]] std::string name() const override { return "active-set"; }
  /// @param warm_start a guess of z: its positive entries are the first active set (else the
  ///        rows with q_i < 0).
  [[nodiscard]] LcpResult solve(const LcpProblem& problem,
                                const Eigen::VectorXd* warm_start = nullptr) override;
  /// The same on a problem given column by column: only the columns of rows that are active at
  /// some iteration are asked for, so with a few hundred active rows among thousands of
  /// candidates the dense M is never formed.
  [[nodiscard]] LcpResult solve(LcpColumns& problem, const Eigen::VectorXd* warm_start = nullptr);
  /// The iteration on any representation of the active-set equations.
  [[nodiscard]] LcpResult solve(ActiveSetEquations& problem,
                                const Eigen::VectorXd* warm_start = nullptr,
                                const Interrupt* interrupt = nullptr);

 private:
  ActiveSetOptions options_;
};

}  // namespace bimrock
