#include <bimrock/solve/fischer_burmeister_newton.hpp>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include <Eigen/LU>
#include <Eigen/UmfPackSupport>

namespace bimrock {
namespace {

using Eigen::Index;
using Eigen::VectorXd;

constexpr double kArmijo = 1e-4;         // the sufficient decrease of the merit
constexpr double kSmallestStep = 1e-10;  // a line search below it has failed
constexpr double kSingularLocal = 1e-12;
/// The merit must fall below kStallRatio of what it was kStallSteps steps before.
constexpr std::size_t kStallSteps = 5;
constexpr double kStallRatio = 0.9;
/// A singular local G (e.g. all three modes of a joint point strictly active, N_gg of rank two)
/// gets alpha_i += kRidge s_i: a regularized Newton step, still checked by the line search.
constexpr double kRidge = 1e-6;

double fischer_burmeister(double a, double b) {
  return a + b - std::hypot(a, b);
}

/// s_i = N_ii, the units of w_i per unit z_i; where N_ii is not positive, the mean of the
/// positive ones.
VectorXd multiplier_scales(const CholmodMatrix& n) {
  VectorXd s = n.diagonal();
  double sum = 0.0;
  Index count = 0;
  for (Index i = 0; i < s.size(); ++i)
    if (s(i) > 0.0) {
      sum += s(i);
      ++count;
    }
  const double typical = count > 0 ? sum / static_cast<double>(count) : 1.0;
  for (Index i = 0; i < s.size(); ++i)
    if (!(s(i) > 0.0))
      s(i) = typical;
  return s;
}

/// An iterate z with x = S^-1 Phi z, w = q + N z - C x measured with S's factor, the size of
/// the terms of each w_i, and Phi(z).
struct Iterate {
  VectorXd z, x, w, w_size, fb;
  double merit = 0.0;
};

class Method {
 public:
  Method(const SplitLcp& lcp, const SpdSolver& s)
      : lcp_(lcp),
        s_(s),
        scale_(multiplier_scales(*lcp.n)),
        c_transposed_(lcp.c->transpose()),
        n_abs_(lcp.n->cwiseAbs()),
        c_abs_(lcp.c->cwiseAbs()),
        s_full_(lcp.k_lower->selfadjointView<Eigen::Lower>()) {}

  [[nodiscard]] Iterate measured(VectorXd z) const {
    Iterate it;
    it.x = z.cwiseAbs().maxCoeff() > 0.0 ? s_.solve(VectorXd(*lcp_.phi * z))
                                         : VectorXd::Zero(s_full_.rows());
    it.w = lcp_.q + *lcp_.n * z - *lcp_.c * it.x;
    it.w_size = lcp_.q.cwiseAbs() + n_abs_ * z.cwiseAbs() + c_abs_ * it.x.cwiseAbs();
    it.z = std::move(z);
    it.fb = fb(it.z, it.w);
    it.merit = 0.5 * it.fb.squaredNorm();
    return it;
  }

  [[nodiscard]] double worst(const Iterate& it) const {
    return measure(it.z, it.w, it.w_size).worst_relative();
  }

  /// The diagonals of the generalized Jacobian J = diag(alpha) + diag(beta) M at `it`.
  void jacobian(const Iterate& it, VectorXd& alpha, VectorXd& beta) const {
    const Index m = lcp_.q.size();
    alpha.resize(m);
    beta.resize(m);
    for (Index i = 0; i < m; ++i) {
      const double a = scale_(i) * it.z(i);
      const double r = std::hypot(a, it.w(i));
      // At r = 0 (z_i = w_i = 0) any unit vector is an element of the generalized Jacobian.
      alpha(i) = scale_(i) * (1.0 - (r > 0.0 ? a / r : M_SQRT1_2));
      beta(i) = 1.0 - (r > 0.0 ? it.w(i) / r : M_SQRT1_2);
    }
  }

  /// The Newton direction (dz, dw = N dz - C dx) at `it`; false where the tangent is singular.
  bool direction(const Iterate& it, VectorXd& dz, VectorXd& dw) {
    const Index m = lcp_.q.size();
    VectorXd alpha;
    VectorXd beta;
    jacobian(it, alpha, beta);
    // Per group of rows (a yield point's modes, consecutive): L = G^-1 diag(beta) couples the
    // tangent, v = G^-1 (-Phi) loads it, dz = v + L C dx.
    struct Local {
      Index first = 0;
      Eigen::MatrixXd coupling;  // L
      VectorXd free;             // v
    };
    std::vector<Local> locals;
    std::vector<Eigen::Triplet<double, std::int64_t>> plastic;
    VectorXd rhs = VectorXd::Zero(s_full_.rows());
    for (Index a = 0; a < m;) {
      Index b = a;
      while (b < m &&
             lcp_.group[static_cast<std::size_t>(b)] == lcp_.group[static_cast<std::size_t>(a)])
        ++b;
      const Index r = b - a;
      Eigen::MatrixXd g = beta.segment(a, r).asDiagonal() * lcp_.n->block(a, a, r, r).toDense();
      g.diagonal() += alpha.segment(a, r);
      Eigen::PartialPivLU<Eigen::MatrixXd> lu(g);
      if (!(lu.rcond() > kSingularLocal)) {
        g.diagonal() += kRidge * scale_.segment(a, r);
        lu.compute(g);
      }
      Local l{a, lu.solve(Eigen::MatrixXd(beta.segment(a, r).asDiagonal())),
              lu.solve(VectorXd(-it.fb.segment(a, r)))};
      std::vector<Index> rows(static_cast<std::size_t>(r));
      for (Index i = 0; i < r; ++i)
        rows[static_cast<std::size_t>(i)] = a + i;
      add_plastic_coupling(*lcp_.phi, c_transposed_, rows.data(), l.coupling, plastic);
      for (Index i = 0; i < r; ++i)
        for (CholmodMatrix::InnerIterator p(*lcp_.phi, a + i); p; ++p)
          rhs(p.row()) += p.value() * l.free(i);
      locals.push_back(std::move(l));
      a = b;
    }
    CholmodMatrix part(s_full_.rows(), s_full_.cols());
    part.setFromTriplets(plastic.begin(), plastic.end());
    tangent_ = s_full_ - part;
    lu_.compute(tangent_);
    if (lu_.info() != Eigen::Success)
      return false;
    const VectorXd dx = lu_.solve(rhs);
    if (!dx.allFinite())
      return false;
    const VectorXd c_dx = *lcp_.c * dx;
    dz.resize(m);
    for (const Local& l : locals) {
      const Index r = l.free.size();
      dz.segment(l.first, r) = l.free + l.coupling * c_dx.segment(l.first, r);
    }
    if (!dz.allFinite())
      return false;
    // w's change along dz measured with S's factor, not the tangent's dx: near a mechanism the
    // tangent is ill-conditioned, and a line search on its own w accepted steps that raised the
    // measured merit.
    dw = *lcp_.n * dz - *lcp_.c * s_.solve(VectorXd(*lcp_.phi * dz));
    return dw.allFinite();
  }

  [[nodiscard]] VectorXd fb(const VectorXd& z, const VectorXd& w) const {
    VectorXd out(z.size());
    for (Index i = 0; i < z.size(); ++i)
      out(i) = fischer_burmeister(scale_(i) * z(i), w(i));
    return out;
  }

 private:
  const SplitLcp& lcp_;
  const SpdSolver& s_;
  VectorXd scale_;
  CholmodMatrix c_transposed_, n_abs_, c_abs_, s_full_;
  // UMFPACK's solves read the matrix again (iterative refinement), and Eigen's wrapper keeps
  // only a view of it: the tangent lives beside its factor.
  CholmodMatrix tangent_;
  Eigen::UmfPackLU<CholmodMatrix> lu_;
};

}  // namespace

LcpResult fischer_burmeister_newton(const SplitLcp& lcp, const SpdSolver& s, const VectorXd& start,
                                    const FischerBurmeisterOptions& options) {
  Method method(lcp, s);
  auto result = [&](LcpStatus status, const Iterate& it, int steps) {
    LcpResult r;
    r.status = status;
    r.z = it.z;
    r.w = it.w;
    r.residuals = measure(it.z, it.w, it.w_size);
    r.steps = steps;
    return r;
  };
  Iterate current = method.measured(start.cwiseMax(0.0));
  Iterate best = current;
  std::vector<double> merits{current.merit};  // after each step
  LcpStatus failure = LcpStatus::iteration_limit;
  int steps = 0;  // directions, each an LU of the tangent
  for (;;) {
    if (method.worst(current) <= options.accuracy) {
      // A root of Phi has z >= 0 up to round-off: the answer is z projected, measured again.
      Iterate projected = method.measured(current.z.cwiseMax(0.0));
      if (method.worst(projected) <= options.accuracy)
        return result(LcpStatus::solved, projected, steps);
    }
    if (steps == options.max_iterations)
      break;
    VectorXd dz;
    VectorXd dw;
    const bool found = method.direction(current, dz, dw);
    ++steps;
    if (!found) {
      failure = LcpStatus::numerical_failure;
      break;
    }
    // Armijo on the merit, w being linear in the step: |Phi|^2 / 2 falls at the rate 2 merit
    // along an exact Newton direction.
    double t = 1.0;
    for (; t >= kSmallestStep; t *= 0.5) {
      const double merit = 0.5 * method.fb(current.z + t * dz, current.w + t * dw).squaredNorm();
      if (merit <= (1.0 - 2.0 * kArmijo * t) * current.merit)
        break;
    }
    if (t < kSmallestStep) {
      failure = LcpStatus::numerical_failure;  // a stationary point of the merit
      break;
    }
    current = method.measured(current.z + t * dz);
    if (current.merit < best.merit)
      best = current;
    // Where the LCP has no solution the merit levels off at a stationary point, well above 0:
    // steps that no longer lower it are given up.
    merits.push_back(current.merit);
    const std::size_t k = merits.size();
    if (k > kStallSteps && merits[k - 1] > kStallRatio * merits[k - 1 - kStallSteps])
      break;
  }
  Iterate answer = method.measured(best.z.cwiseMax(0.0));
  return result(method.worst(answer) <= options.accuracy ? LcpStatus::solved : failure, answer,
                steps);
}

}  // namespace bimrock
