#include <bimrock/solve/reduced_tangent.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SparseCore>

namespace bimrock {

namespace {
/// A local block N_gg whose reciprocal condition is below this is singular (e.g. both slip
/// modes of a frictionless joint point): left to the dense route.
constexpr double kSingularLocal = 1e-12;
/// Shifts, relative to diag(K), under which a tangent that is singular at a mechanism is
/// positive definite (the smallest that works: the kernel's accuracy is about the shift times
/// the condition of K, and the certificate needs ~1e-8), and the inverse iterations that find
/// its kernel.
constexpr double kKernelShifts[] = {1e-12, 1e-10};
constexpr int kInverseIterations = 6;
}  // namespace

struct ReducedTangentEquations::Local {
  std::size_t first;        // its first row's place in `active`
  Eigen::MatrixXd inverse;  // N_gg^-1 of its active rows
};

// C_R x on the rows of one local block (the rates of their yield functions).
Eigen::VectorXd ReducedTangentEquations::strain(const std::vector<Eigen::Index>& active,
                                                const Local& l, const Eigen::VectorXd& x) const {
  Eigen::VectorXd out(l.inverse.rows());
  for (Eigen::Index i = 0; i < out.size(); ++i) {
    double cx = 0.0;
    for (CholmodMatrix::InnerIterator c(c_transposed_,
                                        active[l.first + static_cast<std::size_t>(i)]);
         c; ++c)
      cx += c.value() * x(c.row());
    out(i) = cx;
  }
  return out;
}

Eigen::VectorXd ReducedTangentEquations::mechanism(const CholmodMatrix& tangent,
                                                   const std::vector<Eigen::Index>& active,
                                                   const std::vector<Local>& locals) {
  // A tangent that is not positive definite because the active rows form a mechanism is
  // singular: S v = 0 for the mechanism's displacements v, and with them plastic multipliers
  // r_A = N_AA^-1 C_A v that satisfy M_AA r_A = 0 (the dense route's kernel vector). Found by
  // inverse iteration on S + sigma diag(K), which is positive definite if S is only singular.
  const Eigen::Index n = tangent.rows();
  const Eigen::VectorXd d = lcp_.k_lower->diagonal();
  bool factorized = false;
  for (double shift : kKernelShifts) {
    CholmodMatrix shifted = tangent;
    for (Eigen::Index j = 0; j < n; ++j)
      shifted.coeffRef(j, j) += shift * d(j);
    ++factorizations_;
    tangent_.factored = CholmodMatrix();  // the factor is of the shifted matrix
    factorized = tangent_.cholesky.factorize(shifted);
    if (factorized)
      break;
  }
  if (!factorized)
    return {};  // indefinite beyond round-off: not a mechanism of these rows alone
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i)
    v(i) = 1.0 + 0.5 * std::sin(static_cast<double>(i));  // any start not orthogonal to it
  for (int it = 0; it < kInverseIterations; ++it) {
    v = tangent_.cholesky.solve(Eigen::VectorXd(d.asDiagonal() * v));
    v /= v.norm();
  }
  Eigen::VectorXd r = Eigen::VectorXd::Zero(size());
  for (const Local& l : locals) {
    const Eigen::VectorXd r_local = l.inverse * strain(active, l, v);
    for (Eigen::Index i = 0; i < r_local.size(); ++i)
      r(active[l.first + static_cast<std::size_t>(i)]) = r_local(i);
  }
  if (r.sum() < 0.0)
    r = -r;
  if (!(r.maxCoeff() > 0.0))
    return {};
  r = r.cwiseMax(0.0) / r.maxCoeff();  // certifies_infeasibility tolerates -1e-8 only
  // The certificate is checked on the LCP itself, with K: M r = N r - C K^-1 Phi r.
  const Eigen::VectorXd x = k_.solve(Eigen::VectorXd(*lcp_.phi * r));
  const Eigen::VectorXd mr = *lcp_.n * r - *lcp_.c * x;
  const Eigen::VectorXd sizes = lcp_.n->cwiseAbs() * r + lcp_.c->cwiseAbs() * x.cwiseAbs();
  const double m_max = lcp_.n->diagonal().cwiseAbs().maxCoeff();  // M_ii <= N_ii
  if (!certifies_infeasibility(q(), r, mr, sizes, m_max))
    return {};
  return r;
}

ReducedTangentEquations::ReducedTangentEquations(const SplitLcp& lcp, const SparseCholesky& k,
                                                 TangentFactor& tangent)
    : lcp_(lcp), k_(k), tangent_(tangent), c_transposed_(lcp.c->transpose()) {}

bool ReducedTangentEquations::factorize(const CholmodMatrix& tangent) {
  const CholmodMatrix& kept = tangent_.factored;
  const auto same = [](const auto* a, const auto* b, Eigen::Index size) {
    return std::equal(a, a + size, b);
  };
  if (tangent_.cholesky.factorized() && kept.nonZeros() == tangent.nonZeros() &&
      kept.rows() == tangent.rows() &&
      same(kept.outerIndexPtr(), tangent.outerIndexPtr(), tangent.cols() + 1) &&
      same(kept.innerIndexPtr(), tangent.innerIndexPtr(), tangent.nonZeros()) &&
      same(kept.valuePtr(), tangent.valuePtr(), tangent.nonZeros())) {
    ++reused_;
    return true;
  }
  // The tangent has K's pattern whenever each yield point couples blocks K couples; else
  // (never in the analysis) it is analyzed for its own pattern.
  if (tangent.nonZeros() != tangent_.cholesky.analyzed_nonzeros() ||
      tangent.nonZeros() != lcp_.k_lower->nonZeros())
    tangent_.cholesky.analyze(tangent, 6);
  ++factorizations_;
  if (!tangent_.cholesky.factorize(tangent)) {
    tangent_.factored = CholmodMatrix();
    return false;
  }
  tangent_.factored = tangent;
  return true;
}

ActiveSetEquations::Solution ReducedTangentEquations::solve(const std::vector<Eigen::Index>& active,
                                                            const Damping& damping) {
  const bool damped = damping.factor.size() > 0;
  const Eigen::Index m = size();
  const Eigen::Index n = lcp_.k_lower->rows();
  Solution out;
  out.z = Eigen::VectorXd::Zero(m);
  if (active.empty()) {  // then x = 0: no factorization
    out.w = q();
    out.w_scale = q().cwiseAbs();
    out.regular = true;
    return out;
  }
  // N_AA^-1 group by group (the active rows of a group are consecutive in `active`) and the
  // lower triangle of Phi_A N_AA^-1 C_A.
  std::vector<Local> locals;
  std::vector<Eigen::Triplet<double, std::int64_t>> plastic;
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
    if (damped)
      for (Eigen::Index i = 0; i < r; ++i)
        local(i, i) *= 1.0 + damping.factor(static_cast<Eigen::Index>(a) + i);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(local);
    if (!(lu.rcond() > kSingularLocal))
      return out;
    Local l{a, lu.inverse()};
    for (Eigen::Index i = 0; i < r; ++i) {
      const Eigen::Index row_i = active[a + static_cast<std::size_t>(i)];
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
  if (!factorize(tangent)) {
    out.ray = mechanism(tangent, active, locals);
    return out;
  }
  // z_A with M_AA z_A = -v_A, through the tangent: S x = -Phi_A N_AA^-1 v_A, then
  // z_A = N_AA^-1 (C_A x - v_A). Added to out.z.
  auto add_solution = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::VectorXd> t(locals.size());
    for (std::size_t g = 0; g < locals.size(); ++g) {
      const Local& l = locals[g];
      Eigen::VectorXd v_local(l.inverse.rows());
      for (Eigen::Index i = 0; i < v_local.size(); ++i)
        v_local(i) = v(active[l.first + static_cast<std::size_t>(i)]);
      const Eigen::VectorXd nv = l.inverse * v_local;
      for (Eigen::Index i = 0; i < v_local.size(); ++i)
        for (CholmodMatrix::InnerIterator p(*lcp_.phi,
                                            active[l.first + static_cast<std::size_t>(i)]);
             p; ++p)
          rhs(p.row()) -= p.value() * nv(i);
      t[g] = std::move(v_local);
    }
    const Eigen::VectorXd x = tangent_.cholesky.solve(rhs);
    for (std::size_t g = 0; g < locals.size(); ++g) {
      const Local& l = locals[g];
      const Eigen::VectorXd z_local = l.inverse * (strain(active, l, x) - t[g]);
      for (Eigen::Index i = 0; i < z_local.size(); ++i)
        out.z(active[l.first + static_cast<std::size_t>(i)]) += z_local(i);
    }
  };
  // Near a mechanism the tangent is ill-conditioned (K and the plastic part nearly cancel):
  // one step of refinement on the LCP's own equations, its residual w_A measured with K.
  // The damping D (z - center) is D z on the left and -D center in q.
  Eigen::VectorXd d = Eigen::VectorXd::Zero(m);
  if (damped)
    for (std::size_t r = 0; r < active.size(); ++r)
      d(active[r]) =
          damping.factor(static_cast<Eigen::Index>(r)) * lcp_.n->coeff(active[r], active[r]);
  const Eigen::VectorXd shifted_q =
      damped ? Eigen::VectorXd(q() - d.cwiseProduct(damping.center)) : q();
  add_solution(shifted_q);
  Eigen::VectorXd x = k_.solve(Eigen::VectorXd(*lcp_.phi * out.z));
  add_solution(Eigen::VectorXd(shifted_q + *lcp_.n * out.z - *lcp_.c * x + d.cwiseProduct(out.z)));
  x = k_.solve(Eigen::VectorXd(*lcp_.phi * out.z));
  out.w = q() + *lcp_.n * out.z - *lcp_.c * x;
  out.w_scale =
      q().cwiseAbs() + lcp_.n->cwiseAbs() * out.z.cwiseAbs() + lcp_.c->cwiseAbs() * x.cwiseAbs();
  out.regular = true;
  return out;
}

LcpResult ReducedTangentEquations::result(LcpStatus status, Eigen::VectorXd z, int steps) {
  LcpResult r;
  r.status = status;
  const Eigen::VectorXd x = z.size() > 0 && z.cwiseAbs().maxCoeff() > 0.0
                                ? k_.solve(Eigen::VectorXd(*lcp_.phi * z))
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
