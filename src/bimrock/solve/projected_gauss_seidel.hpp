#pragma once
/// @file Projected (successive over-relaxed) Gauss-Seidel for the LCP (Cryer 1971; Cottle, Pang
/// and Stone 1992, section 5.2): sweep the rows, z_i <- max(0, z_i - omega (M z + q)_i / M_ii).
/// For symmetric M with positive diagonal and 0 < omega < 2 it converges to a solution whenever
/// the LCP is solvable (it minimizes 1/2 z.Mz + q.z over z >= 0); linearly, so it needs many
/// sweeps when M is ill-conditioned. It cannot prove that no solution exists: on an infeasible
/// problem it runs into the iteration limit. The second method to compare Lemke against, and
/// a cheap warm-started solver when consecutive increments differ little.
#include <utility>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

struct PgsOptions {
  /// omega in (0, 2): 1 is plain Gauss-Seidel, > 1 over-relaxation.
  double relaxation = 1.0;
  /// Stop when LcpResiduals::worst_relative() <= tolerance.
  double tolerance = 1e-10;
  int max_iterations = 100000;
};

class ProjectedGaussSeidel final : public LcpSolver {
 public:
  explicit ProjectedGaussSeidel(PgsOptions options = {}) : options_(std::move(options)) {}
  [[nodiscard]] std::string name() const override { return "projected-gauss-seidel"; }
  /// A warm start is projected onto z >= 0 and sweeps start from it. A diagonal entry M_ii <= 0
  /// gives numerical_failure at once (the method does not apply).
  [[nodiscard]] LcpResult solve(const LcpProblem& problem,
                                const Eigen::VectorXd* warm_start = nullptr) override;

 private:
  PgsOptions options_;
};

}  // namespace bimrock
