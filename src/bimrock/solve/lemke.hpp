#pragma once
/// @file Lemke's complementary pivoting method with a covering vector (Lemke 1965; Cottle, Pang
/// and Stone, "The Linear Complementarity Problem", 1992, section 4.4), dense tableau.
///
/// Starting from w = q + e z0 with the artificial z0 just large enough to make w >= 0, it pivots
/// along almost-complementary bases until z0 leaves (a solution) or the entering column has no
/// positive entry (a secondary ray). For copositive-plus M, which includes every positive
/// semi-definite M (associated flow), a ray proves that no solution exists: the structure
/// collapses. For other M (non-associated flow) a ray may also end the method when a solution
/// exists; the status is then still no_solution, and the ray says why.
///
/// Degeneracy: the leaving row is chosen by the lexicographic minimum-ratio rule (the
/// perturbation q + (eps, eps^2, ..., eps^n) in the basis' coordinates), which makes every
/// ratio test unique and so rules out cycling on degenerate problems (zero entries of q, equal
/// rows of M). When z0 ties for leaving it leaves: the method ends at once.
///
/// Robustness (docs/solution-strategy.md): M = N - C K^-1 Phi is formed by cancellation and is
/// singular at a mechanism. So (1) entries below zero_tolerance * max|M_ij| are taken as round-off
/// zeros, (2) rows and columns are equilibrated by powers of two (exact) before pivoting, (3) an
/// entry of the entering column counts as a pivot only if it stands out from the round-off of its
/// own computation, and (4) the result is polished: the final active set {i : z_i basic} is solved
/// again with a dense LU of the unscaled M, and checked in unscaled form. An active set that
/// turns out singular with a certificate of infeasibility (r >= 0, M^T r ~ 0, q . r < 0) is a
/// collapse; any other failed check is a numerical_failure, never a bogus solution.
#include <utility>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

struct LemkeOptions {
  /// Pivot budget; 0 means 50 n + 100 (a pivot per row or two is typical).
  int max_pivots = 0;
  /// An entry d_i of the entering column is a pivot candidate only if
  /// d_i > pivot_tolerance * |row i of B^-1|_1 * |column|_inf, its round-off bound. The same
  /// relative tolerance decides when the polished active set is singular.
  double pivot_tolerance = 1e-11;
  /// Entries |M_ij| <= zero_tolerance * max|M| are round-off residues of a cancellation and
  /// are pivoted on as zeros (the polish and the check still use the exact M). So rows and
  /// columns whose scales differ by more than 1 / zero_tolerance are not supported: scale the
  /// problem first.
  double zero_tolerance = 1e-13;
  /// Scale rows and columns of M by powers of two so their largest entries are near 1.
  bool equilibrate = true;
  /// Covering vector e > 0 in the units of q; empty means e = 1 in the equilibrated problem.
  Eigen::VectorXd covering;
  /// The polished result must satisfy LcpResiduals::worst_relative() <= accuracy.
  double accuracy = 1e-9;
};

class Lemke final : public LcpSolver {
 public:
  explicit Lemke(LemkeOptions options = {}) : options_(std::move(options)) {}
  [[nodiscard]] std::string name() const override { return "lemke"; }
  /// The warm start is ignored: the method always starts from the covering ray.
  [[nodiscard]] LcpResult solve(const LcpProblem& problem,
                                const Eigen::VectorXd* warm_start = nullptr) override;

 private:
  LemkeOptions options_;
};

}  // namespace bimrock
