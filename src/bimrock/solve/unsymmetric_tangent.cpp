#include <bimrock/solve/unsymmetric_tangent.hpp>

#include <cmath>
#include <limits>

#include <Eigen/LU>
#include <Eigen/UmfPackSupport>

namespace bimrock {

namespace {
/// A local block N_gg whose reciprocal condition is below this is singular: left to the dense
/// route (as in reduced_tangent.cpp).
constexpr double kSingularLocal = 1e-12;
/// A solve must meet the active rows' equations to this relative residual, else it is refined
/// once (as in reduced_tangent.cpp).
constexpr double kSolveAccuracy = 1e-10;
}  // namespace

struct UnsymmetricTangentEquations::Lu {
  Eigen::UmfPackLU<CholmodMatrix> lu;
};

UnsymmetricTangentEquations::UnsymmetricTangentEquations(const SplitLcp& lcp, const SpdSolver& s)
    : lcp_(lcp),
      s_(s),
      s_full_(lcp.k_lower->selfadjointView<Eigen::Lower>()),
      c_transposed_(lcp.c->transpose()),
      n_transposed_(lcp.n->transpose()),
      lu_(std::make_unique<Lu>()) {}

UnsymmetricTangentEquations::~UnsymmetricTangentEquations() = default;

void UnsymmetricTangentEquations::residual(const Eigen::VectorXd& z, const Eigen::VectorXd& x,
                                           Eigen::VectorXd& w, Eigen::VectorXd& scale) const {
  const Eigen::Index m = size();
  w.resize(m);
  scale.resize(m);
  for (Eigen::Index i = 0; i < m; ++i) {
    double wi = lcp_.q(i);
    double si = std::abs(wi);
    for (CholmodMatrix::InnerIterator e(n_transposed_, i); e; ++e) {
      wi += e.value() * z(e.row());
      si += std::abs(e.value() * z(e.row()));
    }
    for (CholmodMatrix::InnerIterator e(c_transposed_, i); e; ++e) {
      wi -= e.value() * x(e.row());
      si += std::abs(e.value() * x(e.row()));
    }
    w(i) = wi;
    scale(i) = si;
  }
}

ActiveSetEquations::Solution UnsymmetricTangentEquations::solve(
    const std::vector<Eigen::Index>& active, const Damping& damping, Check check) {
  const bool damped = damping.factor.size() > 0;
  const Eigen::Index m = size();
  const Eigen::Index n = s_full_.rows();
  Solution out;
  out.z = Eigen::VectorXd::Zero(m);
  if (active.empty()) {
    out.w = q();
    out.w_scale = q().cwiseAbs();
    out.regular = true;
    return out;
  }
  // N_AA^-1 group by group (a group's active rows are consecutive in `active`), and the
  // tangent's plastic part Phi_A N_AA^-1 C_A as triplets: each term couples only the unknowns
  // of the blocks its yield point joins.
  struct Local {
    std::size_t first;
    Eigen::MatrixXd inverse;
  };
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
    const Eigen::MatrixXd inverse = lu.inverse();
    for (Eigen::Index i = 0; i < r; ++i)
      for (CholmodMatrix::InnerIterator p(*lcp_.phi, active[a + static_cast<std::size_t>(i)]); p;
           ++p)
        for (Eigen::Index j = 0; j < r; ++j)
          for (CholmodMatrix::InnerIterator c(c_transposed_,
                                              active[a + static_cast<std::size_t>(j)]);
               c; ++c)
            plastic.emplace_back(p.row(), c.row(), p.value() * inverse(i, j) * c.value());
    locals.push_back(Local{a, inverse});
    a = b;
  }
  CholmodMatrix part(n, n);
  part.setFromTriplets(plastic.begin(), plastic.end());
  const CholmodMatrix tangent = s_full_ - part;
  lu_->lu.compute(tangent);
  ++factorizations_;
  if (lu_->lu.info() != Eigen::Success)
    return out;  // singular: the dense route decides
  // z_A with M_AA z_A = -v_A through the tangent, added to out.z; x is the tangent's own.
  Eigen::VectorXd x;
  auto add_solution = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
    std::vector<Eigen::VectorXd> v_locals(locals.size());
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
      v_locals[g] = std::move(v_local);
    }
    x = lu_->lu.solve(rhs);
    for (std::size_t g = 0; g < locals.size(); ++g) {
      const Local& l = locals[g];
      Eigen::VectorXd cx(l.inverse.rows());
      for (Eigen::Index i = 0; i < cx.size(); ++i) {
        double sum = 0.0;
        for (CholmodMatrix::InnerIterator c(c_transposed_,
                                            active[l.first + static_cast<std::size_t>(i)]);
             c; ++c)
          sum += c.value() * x(c.row());
        cx(i) = sum;
      }
      const Eigen::VectorXd z_local = l.inverse * (cx - v_locals[g]);
      for (Eigen::Index i = 0; i < z_local.size(); ++i)
        out.z(active[l.first + static_cast<std::size_t>(i)]) += z_local(i);
    }
  };
  // The damping D (z - center) is D z on the left and -D center in q.
  Eigen::VectorXd d = Eigen::VectorXd::Zero(m);
  if (damped)
    for (std::size_t r = 0; r < active.size(); ++r)
      d(active[r]) =
          damping.factor(static_cast<Eigen::Index>(r)) * lcp_.n->coeff(active[r], active[r]);
  const Eigen::VectorXd shifted_q =
      damped ? Eigen::VectorXd(q() - d.cwiseProduct(damping.center)) : q();
  add_solution(shifted_q);
  if (check == Check::from_solve) {
    residual(out.z, x, out.w, out.w_scale);
    out.measured = false;
    out.regular = true;
    return out;
  }
  // Measured with S's own factor: the worst relative residual of the active rows' equations.
  auto measure = [&] {
    x = s_.solve(Eigen::VectorXd(*lcp_.phi * out.z));
    residual(out.z, x, out.w, out.w_scale);
    double worst = 0.0;
    for (Eigen::Index i : active) {
      const double res = out.w(i) + d(i) * (out.z(i) - (damped ? damping.center(i) : 0.0));
      if (res == 0.0)
        continue;
      const double relative = std::abs(res) / out.w_scale(i);
      if (std::isnan(relative))
        return std::numeric_limits<double>::infinity();
      worst = std::max(worst, relative);
    }
    return worst;
  };
  double worst = measure();
  if (!(worst <= kSolveAccuracy)) {
    add_solution(
        Eigen::VectorXd(shifted_q + *lcp_.n * out.z - *lcp_.c * x + d.cwiseProduct(out.z)));
    worst = measure();
  }
  out.regular = std::isfinite(worst);
  return out;
}

LcpResult UnsymmetricTangentEquations::result(LcpStatus status, Eigen::VectorXd z, int steps) {
  LcpResult r;
  r.status = status;
  const Eigen::VectorXd x = z.size() > 0 && z.cwiseAbs().maxCoeff() > 0.0
                                ? s_.solve(Eigen::VectorXd(*lcp_.phi * z))
                                : Eigen::VectorXd::Zero(s_full_.rows());
  Eigen::VectorXd sizes;
  residual(z, x, r.w, sizes);
  r.residuals = measure(z, r.w, sizes);
  r.z = std::move(z);
  r.steps = steps;
  return r;
}

}  // namespace bimrock
