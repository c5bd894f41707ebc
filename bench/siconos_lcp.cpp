#include "siconos_lcp.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <bimrock/solve/active_set_lcp.hpp>

#include <LCP_Solvers.h>
#include <LinearComplementarityProblem.h>
#include <NonSmoothDrivers.h>
#include <NumericsMatrix.h>
#include <SolverOptions.h>
#include <lcp_cst.h>

namespace bimrock::bench {
namespace {

int solver_id(SiconosMethod method) {
  switch (method) {
    case SiconosMethod::lemke:
      return SICONOS_LCP_LEMKE;
    case SiconosMethod::newton_min_fb:
      return SICONOS_LCP_NEWTON_MIN_FBLSA;
  }
  throw std::logic_error("unknown Siconos method");
}

struct OptionsDeleter {
  void operator()(SolverOptions* o) const { solver_options_delete(o); }
};
// The matrix holds a pointer to our data: free the wrapper, not the entries.
struct MatrixDeleter {
  void operator()(NumericsMatrix* m) const { NM_free_not_dense(m); }
};

// Powers of two r, c that bring the largest entry of every row and column of diag(r) M diag(c)
// near 1 (alternating sweeps over rows and columns; exact in floating point). Column by column:
// M is column-major.
void equilibration(const Eigen::MatrixXd& m, Eigen::VectorXd& r, Eigen::VectorXd& c) {
  const Eigen::Index n = m.rows();
  r = Eigen::VectorXd::Ones(n);
  c = Eigen::VectorXd::Ones(n);
  auto power_of_two = [](double largest) {
    return largest > 0.0 ? std::exp2(-std::round(std::log2(largest))) : 1.0;
  };
  for (int sweep = 0; sweep < 4; ++sweep) {
    Eigen::VectorXd row_max = Eigen::VectorXd::Zero(n);
    for (Eigen::Index j = 0; j < n; ++j)
      row_max = row_max.cwiseMax(m.col(j).cwiseAbs() * c(j));
    for (Eigen::Index i = 0; i < n; ++i)
      r(i) *= power_of_two(r(i) * row_max(i));
    for (Eigen::Index j = 0; j < n; ++j)
      c(j) *= power_of_two(c(j) * m.col(j).cwiseAbs().cwiseProduct(r).maxCoeff());
  }
}

}  // namespace

std::string SiconosLcp::name() const {
  return method_ == SiconosMethod::lemke ? "siconos-lemke" : "siconos-newton-min-fb";
}

LcpResult SiconosLcp::solve(const LcpProblem& problem, const Eigen::VectorXd* warm_start) {
  check_lcp(problem);
  const Eigen::Index n = problem.size();
  Eigen::VectorXd z =
      warm_start && warm_start->size() == n ? *warm_start : Eigen::VectorXd::Zero(n).eval();
  int iterations = 0;
  LcpStatus status = LcpStatus::solved;
  if (equilibrate_ && n > 0) {
    // w' = diag(r) w = M' z' + q' with M' = diag(r) M diag(c), q' = diag(r) q, z = diag(c) z'.
    Eigen::VectorXd r, c;
    equilibration(problem.m, r, c);
    const LcpProblem scaled{r.asDiagonal() * problem.m * c.asDiagonal(), r.cwiseProduct(problem.q)};
    Eigen::VectorXd z_scaled = z.cwiseQuotient(c);
    status = run(scaled, z_scaled, iterations);
    z = z_scaled.cwiseProduct(c);
  } else {
    status = run(problem, z, iterations);
  }
  return make_lcp_result(problem, status, std::move(z), iterations);
}

LcpStatus SiconosLcp::run(const LcpProblem& problem, Eigen::VectorXd& z, int& iterations) {
  const Eigen::Index n = problem.size();
  if (n > std::numeric_limits<int>::max() / 64)
    throw std::invalid_argument("SiconosLcp: problem too large for Siconos' int sizes");
  const int ni = static_cast<int>(n);
  // Siconos reads M and q without writing them (its solvers work on copies: Lemke's tableau,
  // Newton's Jacobian), but its C interface takes them non-const.
  std::unique_ptr<NumericsMatrix, MatrixDeleter> m(
      NM_create_from_data(NM_DENSE, ni, ni, const_cast<double*>(problem.m.data())));
  LinearComplementarityProblem lcp{ni, m.get(), const_cast<double*>(problem.q.data())};
  std::unique_ptr<SolverOptions, OptionsDeleter> options(solver_options_create(solver_id(method_)));
  // Our budgets: Lemke's pivots as LemkeOptions' default (50 n + 100), Newton's iterations as
  // the active-set method's (each is one dense solve).
  options->iparam[SICONOS_IPARAM_MAX_ITER] =
      method_ == SiconosMethod::lemke ? 50 * ni + 100 : ActiveSetOptions{}.max_iterations;
  Eigen::VectorXd w = Eigen::VectorXd::Zero(n);
  info_ = linearComplementarity_driver(&lcp, z.data(), w.data(), options.get());
  error_ = options->dparam[SICONOS_DPARAM_RESIDU];
  iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
  if (info_ == 0)
    return LcpStatus::solved;
  return iterations >= options->iparam[SICONOS_IPARAM_MAX_ITER] ? LcpStatus::iteration_limit
                                                                : LcpStatus::numerical_failure;
}

SolutionDifference compare_solutions(const Eigen::VectorXd& z, const Eigen::VectorXd& ref) {
  if (z.size() != ref.size())
    throw std::invalid_argument("compare_solutions: sizes differ");
  SolutionDifference d;
  if (z.size() == 0)
    return d;
  d.absolute = (z - ref).cwiseAbs().maxCoeff();
  const double size = ref.cwiseAbs().maxCoeff();
  d.scaled = d.absolute / std::max(1.0, size);
  d.relative = size > 0.0 ? d.absolute / size : d.absolute;
  return d;
}

}  // namespace bimrock::bench
