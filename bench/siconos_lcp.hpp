#pragma once
// Siconos Numerics' dense LCP solvers behind our LcpSolver interface, and the comparison of two
// solutions of one LCP: a peer for our solvers, in bench/ only. Siconos is an optional
// dependency of the benchmarks: this file and its .cpp are compiled only when it is found
// (bench/CMakeLists.txt), and no Siconos header leaks out of the .cpp.
#include <string>

#include <bimrock/solve/lcp.hpp>

namespace bimrock::bench {

/// Which Siconos solver (the numbers of Siconos' lcp_cst.h, mapped in the .cpp).
enum class SiconosMethod {
  lemke,          ///< SICONOS_LCP_LEMKE: lexicographic Lemke on a dense tableau
  newton_min_fb,  ///< SICONOS_LCP_NEWTON_MIN_FBLSA: semismooth Newton on min(z, w) with a
                  ///< Fischer-Burmeister line search
};

/// Siconos' linearComplementarity_driver on the dense M (column-major, as Eigen stores it).
/// Options are Siconos' defaults (solver_options_create) except the budgets, set to ours: Lemke
/// 50 n + 100 pivots (Siconos: 10 000), Newton 50 iterations (Siconos: 1 000; each is a dense
/// LU). Newton starts from the warm start when one is given, as our active-set method does.
///
/// Scaling: Siconos' stopping test, ||min(z, w)||_2 / ||q||_2 <= tol (1e-10 for Newton), mixes
/// the units of z and w. In our LCPs z is in metres (~1e-6) and w in newtons per metre (~1e5), so
/// on the raw problem Newton stops with z wrong by up to 1e-6 relative while claiming success.
/// With `equilibrate` (the default) Siconos is given the same LCP with its rows and columns
/// scaled by powers of two (exact) so that every row and column of M has its largest entry near
/// 1: z and w are then both O(1) and its test means what it says. The scaling is inside
/// the timed solve (O(n^2), small beside either method); z is scaled back.
///
/// The result's status says only what Siconos claims: solved when its info is 0 (converged and
/// its own error below its tolerance: 1e-6 for Lemke, 1e-10 for Newton), iteration_limit when
/// the budget ran out, numerical_failure otherwise (Lemke: also a secondary ray, which Siconos
/// does not tell apart from a failure). w and the residuals are recomputed by make_lcp_result
/// from the unscaled problem, the same measure as for ours.
class SiconosLcp final : public LcpSolver {
 public:
  explicit SiconosLcp(SiconosMethod method, bool equilibrate = true)
      : method_(method), equilibrate_(equilibrate) {}
  [[nodiscard]] std::string name() const override;
  /// @param warm_start Newton's first iterate (else z = 0); Lemke ignores it.
  [[nodiscard]] LcpResult solve(const LcpProblem& problem,
                                const Eigen::VectorXd* warm_start = nullptr) override;
  /// Siconos' info and own error (on the problem it was given) of the last solve.
  [[nodiscard]] int last_info() const { return info_; }
  [[nodiscard]] double last_error() const { return error_; }

 private:
  // Siconos on exactly this problem: z, and the status it claims.
  LcpStatus run(const LcpProblem& problem, Eigen::VectorXd& z, int& iterations);

  SiconosMethod method_;
  bool equilibrate_;
  int info_ = 0;
  double error_ = 0.0;
};

/// How far a solution z is from a reference solution `ref` of the same LCP.
struct SolutionDifference {
  double absolute = 0.0;  ///< max_i |z_i - ref_i|
  /// The brief's measure: max_i |z_i - ref_i| / max(1, |ref|_inf). With z in metres (of order
  /// 1e-6 here) it is an absolute difference in practice.
  double scaled = 0.0;
  /// max_i |z_i - ref_i| / |ref|_inf (the absolute difference when ref = 0): invariant under a
  /// change of units, the one the benchmarks judge by.
  double relative = 0.0;
};

[[nodiscard]] SolutionDifference compare_solutions(const Eigen::VectorXd& z,
                                                   const Eigen::VectorXd& ref);

/// A solver that claims success must agree with the reference to this (relative).
inline constexpr double kAgreement = 1e-9;

}  // namespace bimrock::bench
