#include <bimrock/solve/split_lcp_equations.hpp>

#include <cmath>
#include <limits>
#include <utility>

#include <Eigen/LU>

namespace bimrock {

namespace {
/// A local block N_gg whose reciprocal condition is below this is singular.
constexpr double kSingularLocal = 1e-12;
}  // namespace

void add_plastic_coupling(const CholmodMatrix& phi, const CholmodMatrix& c_transposed,
                          const Eigen::Index* rows, const Eigen::MatrixXd& local,
                          std::vector<Eigen::Triplet<double, std::int64_t>>& out) {
  for (Eigen::Index i = 0; i < local.rows(); ++i)
    for (CholmodMatrix::InnerIterator p(phi, rows[i]); p; ++p)
      for (Eigen::Index j = 0; j < local.cols(); ++j)
        for (CholmodMatrix::InnerIterator c(c_transposed, rows[j]); c; ++c)
          out.emplace_back(p.row(), c.row(), p.value() * local(i, j) * c.value());
}

SplitLcpEquations::SplitLcpEquations(const SplitLcp& lcp, const SpdSolver& s)
    : lcp_(lcp), s_(s), c_transposed_(lcp.c->transpose()), n_transposed_(lcp.n->transpose()) {}

ActiveSetEquations::Solution SplitLcpEquations::start(
    const std::vector<Eigen::Index>& active) const {
  Solution out;
  out.z = Eigen::VectorXd::Zero(size());
  if (active.empty()) {
    out.w = q();
    out.w_scale = q().cwiseAbs();
    out.regular = true;
  }
  return out;
}

std::optional<std::vector<SplitLcpEquations::Local>> SplitLcpEquations::locals(
    const std::vector<Eigen::Index>& active, const Damping& damping) const {
  const bool damped = damping.factor.size() > 0;
  std::vector<Local> out;
  for (std::size_t a = 0; a < active.size();) {
    std::size_t b = a;
    while (b < active.size() && group(active[b]) == group(active[a]))
      ++b;
    const auto r = static_cast<Eigen::Index>(b - a);
    Eigen::MatrixXd block(r, r);
    for (Eigen::Index i = 0; i < r; ++i)
      for (Eigen::Index j = 0; j < r; ++j)
        block(i, j) = lcp_.n->coeff(active[a + static_cast<std::size_t>(i)],
                                    active[a + static_cast<std::size_t>(j)]);
    if (damped)
      for (Eigen::Index i = 0; i < r; ++i)
        block(i, i) *= 1.0 + damping.factor(static_cast<Eigen::Index>(a) + i);
    const Eigen::PartialPivLU<Eigen::MatrixXd> lu(block);
    if (!(lu.rcond() > kSingularLocal))
      return std::nullopt;
    out.push_back(Local{a, std::move(block), lu.inverse()});
    a = b;
  }
  return out;
}

Eigen::VectorXd SplitLcpEquations::strain(const std::vector<Eigen::Index>& active, const Local& l,
                                          const Eigen::VectorXd& x) const {
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

Eigen::VectorXd SplitLcpEquations::plastic_load(const std::vector<Eigen::Index>& active,
                                                const std::vector<Local>& locals,
                                                const Eigen::VectorXd& v,
                                                std::vector<Eigen::VectorXd>& v_locals) const {
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(lcp_.k_lower->rows());
  v_locals.assign(locals.size(), Eigen::VectorXd());
  for (std::size_t g = 0; g < locals.size(); ++g) {
    const Local& l = locals[g];
    Eigen::VectorXd v_local(l.inverse.rows());
    for (Eigen::Index i = 0; i < v_local.size(); ++i)
      v_local(i) = v(active[l.first + static_cast<std::size_t>(i)]);
    const Eigen::VectorXd nv = l.inverse * v_local;
    for (Eigen::Index i = 0; i < v_local.size(); ++i)
      for (CholmodMatrix::InnerIterator p(*lcp_.phi, active[l.first + static_cast<std::size_t>(i)]);
           p; ++p)
        rhs(p.row()) -= p.value() * nv(i);
    v_locals[g] = std::move(v_local);
  }
  return rhs;
}

void SplitLcpEquations::add_multipliers(const std::vector<Eigen::Index>& active,
                                        const std::vector<Local>& locals, const Eigen::VectorXd& x,
                                        const std::vector<Eigen::VectorXd>& v_locals,
                                        Eigen::VectorXd& z) const {
  for (std::size_t g = 0; g < locals.size(); ++g) {
    const Local& l = locals[g];
    const Eigen::VectorXd z_local = l.inverse * (strain(active, l, x) - v_locals[g]);
    for (Eigen::Index i = 0; i < z_local.size(); ++i)
      z(active[l.first + static_cast<std::size_t>(i)]) += z_local(i);
  }
}

Eigen::VectorXd SplitLcpEquations::damping_terms(const std::vector<Eigen::Index>& active,
                                                 const Damping& damping) const {
  Eigen::VectorXd d = Eigen::VectorXd::Zero(size());
  if (damping.factor.size() > 0)
    for (std::size_t r = 0; r < active.size(); ++r)
      d(active[r]) =
          damping.factor(static_cast<Eigen::Index>(r)) * lcp_.n->coeff(active[r], active[r]);
  return d;
}

double SplitLcpEquations::solve_through(const std::vector<Eigen::Index>& active,
                                        const std::vector<Local>& locals, const Damping& damping,
                                        Check check, const LinearSolve& tangent_solve,
                                        Solution& out) const {
  // z_A with M_AA z_A = -v_A through the tangent: S x = -Phi_A N_AA^-1 v_A, then
  // z_A = N_AA^-1 (C_A x - v_A), added to out.z; x is the last solve's, then as measured.
  Eigen::VectorXd x;
  auto add_solution = [&](const Eigen::VectorXd& v) {
    std::vector<Eigen::VectorXd> v_locals;
    x = tangent_solve(plastic_load(active, locals, v, v_locals));
    add_multipliers(active, locals, x, v_locals, out.z);
  };
  // The damping D (z - center) is D z on the left and -D center in q.
  const Eigen::VectorXd d = damping_terms(active, damping);
  const Eigen::VectorXd shifted_q =
      damping.factor.size() > 0 ? Eigen::VectorXd(q() - d.cwiseProduct(damping.center)) : q();
  add_solution(shifted_q);
  if (check == Check::from_solve) {
    // w from the tangent's own x: w_A = 0 up to its round-off, and w off A as the solve left it.
    residual(out.z, x, out.w, out.w_scale);
    out.measured = false;
    return 0.0;
  }
  double worst = measure_active(active, d, damping, out, x);
  // Near a mechanism the tangent is ill-conditioned (S and the plastic part nearly cancel):
  // then one step of refinement on the LCP's own equations, its residual measured with S.
  if (!(worst <= kSolveAccuracy)) {
    add_solution(
        Eigen::VectorXd(shifted_q + *lcp_.n * out.z - *lcp_.c * x + d.cwiseProduct(out.z)));
    worst = measure_active(active, d, damping, out, x);
  }
  return worst;
}

double SplitLcpEquations::measure_active(const std::vector<Eigen::Index>& active,
                                         const Eigen::VectorXd& d, const Damping& damping,
                                         Solution& out, Eigen::VectorXd& x) const {
  const bool damped = damping.factor.size() > 0;
  x = s_.solve(Eigen::VectorXd(*lcp_.phi * out.z));
  residual(out.z, x, out.w, out.w_scale);
  double worst = 0.0;
  for (Eigen::Index i : active) {
    const double res = out.w(i) + d(i) * (out.z(i) - (damped ? damping.center(i) : 0.0));
    if (res == 0.0)
      continue;  // also where the row's scale is 0
    const double relative = std::abs(res) / out.w_scale(i);
    if (std::isnan(relative))
      return std::numeric_limits<double>::infinity();
    worst = std::max(worst, relative);
  }
  return worst;
}

void SplitLcpEquations::residual(const Eigen::VectorXd& z, const Eigen::VectorXd& x,
                                 Eigen::VectorXd& w, Eigen::VectorXd& scale) const {
  const Eigen::Index m = size();
  w.resize(m);
  scale.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    double wi = lcp_.q(i);
    double si = std::abs(wi);
    for (CholmodMatrix::InnerIterator e(n_transposed_, i); e; ++e) {
      const double term = e.value() * z(e.row());
      wi += term;
      si += std::abs(term);
    }
    for (CholmodMatrix::InnerIterator e(c_transposed_, i); e; ++e) {
      const double term = e.value() * x(e.row());
      wi -= term;
      si += std::abs(term);
    }
    w(i) = wi;
    scale(i) = si;
  }
}

LcpResult SplitLcpEquations::result(LcpStatus status, Eigen::VectorXd z, int steps) {
  LcpResult r;
  r.status = status;
  const Eigen::VectorXd x = z.size() > 0 && z.cwiseAbs().maxCoeff() > 0.0
                                ? s_.solve(Eigen::VectorXd(*lcp_.phi * z))
                                : Eigen::VectorXd::Zero(lcp_.k_lower->rows());
  Eigen::VectorXd sizes;
  residual(z, x, r.w, sizes);
  r.residuals = measure(z, r.w, sizes);
  r.z = std::move(z);
  r.steps = steps;
  return r;
}

}  // namespace bimrock
