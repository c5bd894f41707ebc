#pragma once
/// @file Brute force over the 2^n complementary bases: for every active set A, solve
/// M_AA z_A = -q_A (z = 0 elsewhere) and keep z if it satisfies the LCP. Exponential, so only
/// for tests and small n: the oracle Lemke is checked against.
///
/// Only active sets with a nonsingular M_AA are tried. That misses no solution when M is a
/// P-matrix (every M_AA nonsingular) or symmetric positive semi-definite: there, if any solution
/// exists, one with support B has M_BB nonsingular (a vertex of the solution set's face gives
/// M_{.B} full column rank, and M_BB v = 0 implies M v = 0 for such M). So for these classes
/// "none found" proves that the LCP has no solution.
#include <utility>
#include <vector>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

struct EnumerationOptions {
  /// A basis solution counts when LcpResiduals::worst_relative() <= tolerance.
  double tolerance = 1e-10;
  /// M_AA is singular when a pivot of its full-pivoting LU falls below this fraction of the
  /// largest.
  double singular_tolerance = 1e-12;
  /// Larger problems are refused (std::invalid_argument): 2^20 bases are already a lot.
  int max_size = 20;
};

/// Every distinct solution with a nonsingular M_AA (see the file comment), fewest active first.
[[nodiscard]] std::vector<Eigen::VectorXd> enumerate_lcp_solutions(
    const LcpProblem& problem, const EnumerationOptions& options = {});

class LcpEnumeration final : public LcpSolver {
 public:
  explicit LcpEnumeration(EnumerationOptions options = {}) : options_(std::move(options)) {}
  [[nodiscard]] std::string name() const override { return "enumeration"; }
  /// The solution with the fewest active rows, or no_solution when there is none (a proof for
  /// P-matrices and symmetric positive semi-definite M). The warm start is ignored.
  [[nodiscard]] LcpResult solve(const LcpProblem& problem,
                                const Eigen::VectorXd* warm_start = nullptr) override;

 private:
  EnumerationOptions options_;
};

}  // namespace bimrock
