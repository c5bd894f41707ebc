#include <bimrock/solve/reduced_tangent.hpp>

#include <chrono>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SparseCore>

namespace bimrock {

namespace {
/// A local block N_gg whose reciprocal condition is below this is singular (e.g. both slip
/// modes of a frictionless joint point): left to the dense route.
constexpr double kSingularLocal = 1e-12;
}  // namespace

ReducedTangentEquations::ReducedTangentEquations(const SplitLcp& lcp, const SparseCholesky& k,
                                                 SparseCholesky& tangent)
    : lcp_(lcp), k_(k), tangent_(tangent), c_transposed_(lcp.c->transpose()) {}

ActiveSetEquations::Solution ReducedTangentEquations::solve(
    const std::vector<Eigen::Index>& active) {
  const Eigen::Index m = size();
  const Eigen::Index n = lcp_.k_lower->rows();
  Solution out;
  out.z = Eigen::VectorXd::Zero(m);
  if (active.empty()) {  // then x = 0: no factorization
    out.w = q();
    out.regular = true;
    return out;
  }
  // N_AA^-1 group by group (the active rows of a group are consecutive in `active`), the lower
  // triangle of Phi_A N_AA^-1 C_A, and the right-hand side -Phi_A N_AA^-1 q_A.
  struct Local {
    std::size_t first;
    Eigen::MatrixXd inverse;
  };
  std::vector<Local> locals;
  std::vector<Eigen::Triplet<double, std::int64_t>> plastic;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (std::size_t a = 0; a < active.size();) {
    std::size_t b = a;
    while (b < active.size() && group(active[b]) == group(active[a]))
      ++b;
    const auto r = static_cast<Eigen::Index>(b - a);
    Eigen::MatrixXd local(r, r);
    for (Eigen::Index i = 0; i < r; ++i)
      for (Eigen::Index j = 0; j < r; ++j)
        local(i, j) = lcp_.n->coeff(active[a + static_cast<std::size_t>(i)],
                                    active[a + static_cast<std::size_t>(j)]);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(local);
    if (!(lu.rcond() > kSingularLocal))
      return out;
    Local l{a, lu.inverse()};
    Eigen::VectorXd q_local(r);
    for (Eigen::Index i = 0; i < r; ++i)
      q_local(i) = q()(active[a + static_cast<std::size_t>(i)]);
    const Eigen::VectorXd t = l.inverse * q_local;
    for (Eigen::Index i = 0; i < r; ++i) {
      const Eigen::Index row_i = active[a + static_cast<std::size_t>(i)];
      for (CholmodMatrix::InnerIterator p(*lcp_.phi, row_i); p; ++p)
        rhs(p.row()) -= p.value() * t(i);
      for (Eigen::Index j = 0; j < r; ++j) {
        const double coefficient = l.inverse(i, j);
        if (coefficient == 0.0)
          continue;
        const Eigen::Index row_j = active[a + static_cast<std::size_t>(j)];
        for (CholmodMatrix::InnerIterator p(*lcp_.phi, row_i); p; ++p)
          for (CholmodMatrix::InnerIterator c(c_transposed_, row_j); c; ++c)
            if (p.row() >= c.row())
              plastic.emplace_back(p.row(), c.row(), p.value() * coefficient * c.value());
      }
    }
    locals.push_back(std::move(l));
    a = b;
  }
  CholmodMatrix plastic_lower(n, n);
  plastic_lower.setFromTriplets(plastic.begin(), plastic.end());
  const CholmodMatrix tangent = *lcp_.k_lower - plastic_lower;

  // The tangent has K's pattern whenever each yield point couples blocks K couples; else
  // (never in the analysis) it is analyzed for its own pattern.
  if (tangent.nonZeros() != tangent_.analyzed_nonzeros() ||
      tangent.nonZeros() != lcp_.k_lower->nonZeros())
    tangent_.analyze(tangent, 6);
  const auto start = std::chrono::steady_clock::now();
  const bool positive_definite = tangent_.factorize(tangent);
  factorization_seconds_ +=
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ++factorizations_;
  if (!positive_definite)
    return out;
  Eigen::VectorXd x = tangent_.solve(rhs);
  x += tangent_.solve(Eigen::VectorXd(rhs - tangent.selfadjointView<Eigen::Lower>() * x));

  for (const Local& l : locals) {
    const auto r = l.inverse.rows();
    Eigen::VectorXd strain_minus_q(r);  // C_R x - q_R
    for (Eigen::Index i = 0; i < r; ++i) {
      const Eigen::Index row = active[l.first + static_cast<std::size_t>(i)];
      double cx = 0.0;
      for (CholmodMatrix::InnerIterator c(c_transposed_, row); c; ++c)
        cx += c.value() * x(c.row());
      strain_minus_q(i) = cx - q()(row);
    }
    const Eigen::VectorXd z_local = l.inverse * strain_minus_q;
    for (Eigen::Index i = 0; i < r; ++i)
      out.z(active[l.first + static_cast<std::size_t>(i)]) = z_local(i);
  }
  out.w = q() + *lcp_.n * out.z - *lcp_.c * x;
  out.regular = true;
  return out;
}

LcpResult ReducedTangentEquations::result(LcpStatus status, Eigen::VectorXd z, int steps) {
  LcpResult r;
  r.status = status;
  const Eigen::VectorXd x =
      z.size() > 0 && z.cwiseAbs().maxCoeff() > 0.0 ? k_.solve(Eigen::VectorXd(*lcp_.phi * z))
                                    : Eigen::VectorXd::Zero(lcp_.k_lower->rows());
  r.w = q() + *lcp_.n * z - *lcp_.c * x;
  const Eigen::VectorXd sizes =
      q().cwiseAbs() + lcp_.n->cwiseAbs() * z.cwiseAbs() + lcp_.c->cwiseAbs() * x.cwiseAbs();
  r.residuals = measure(z, r.w, sizes);
  r.z = std::move(z);
  r.steps = steps;
  return r;
}

}  // namespace bimrock
