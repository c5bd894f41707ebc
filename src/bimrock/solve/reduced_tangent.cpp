#include <bimrock/solve/reduced_tangent.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <utility>

#include <Eigen/LU>
#include <Eigen/SparseCore>

namespace bimrock {

namespace {
/// Shifts, relative to diag(K), under which a tangent that is singular at a mechanism is
/// positive definite (the smallest that works: the kernel's accuracy is about the shift times
/// the condition of K, and the certificate needs ~1e-8), and the inverse iterations that find
/// its kernel.
constexpr double kKernelShifts[] = {1e-12, 1e-10};
constexpr int kInverseIterations = 6;
}  // namespace

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
    factorized = tangent_.cholesky.factorize(shifted);  // a factor of no tangent
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
  const Eigen::VectorXd x = s_.solve(Eigen::VectorXd(*lcp_.phi * r));
  const Eigen::VectorXd mr = *lcp_.n * r - *lcp_.c * x;
  const Eigen::VectorXd sizes = lcp_.n->cwiseAbs() * r + lcp_.c->cwiseAbs() * x.cwiseAbs();
  const double m_max = lcp_.n->diagonal().cwiseAbs().maxCoeff();  // M_ii <= N_ii
  if (!certifies_infeasibility(q(), r, mr, sizes, m_max))
    return {};
  return r;
}

ReducedTangentEquations::ReducedTangentEquations(const SplitLcp& lcp, const SpdSolver& k,
                                                 TangentFactor& tangent, TangentUpdateLimits limits)
    : SplitLcpEquations(lcp, k),
      tangent_(tangent),
      n_diagonal_(lcp.n->diagonal()),
      limits_(limits) {}

bool ReducedTangentEquations::factorize(const CholmodMatrix& tangent) {
  // The tangent has K's pattern whenever each yield point couples blocks K couples; else
  // (never in the analysis) it is analyzed for its own pattern.
  if (tangent.nonZeros() != tangent_.cholesky.analyzed_nonzeros() ||
      tangent.nonZeros() != lcp_.k_lower->nonZeros())
    tangent_.cholesky.analyze(tangent, 6);
  ++factorizations_;
  return tangent_.cholesky.factorize(tangent);
}

int ReducedTangentEquations::mode(Eigen::Index row) const {
  Eigen::Index first = row;
  while (first > 0 && group(first - 1) == group(row))
    --first;
  return static_cast<int>(row - first);
}

const CholmodMatrix& ReducedTangentEquations::form_tangent(const std::vector<Eigen::Index>& active,
                                                           const std::vector<Local>& locals) {
  const CholmodMatrix& k = *lcp_.k_lower;
  CholmodMatrix& t = tangent_.matrix;
  const bool k_pattern =
      t.rows() == k.rows() && t.nonZeros() == k.nonZeros() &&
      std::equal(k.outerIndexPtr(), k.outerIndexPtr() + k.cols() + 1, t.outerIndexPtr()) &&
      std::equal(k.innerIndexPtr(), k.innerIndexPtr() + k.nonZeros(), t.innerIndexPtr());
  if (k_pattern)
    std::copy(k.valuePtr(), k.valuePtr() + k.nonZeros(), t.valuePtr());
  else
    t = k;
  // Each term Phi_g N_gg^-1 C_g of the lower triangle, subtracted where it falls; a term outside
  // K's pattern (a yield point coupling blocks K does not: never in the analysis) is gathered
  // and added with a pattern of its own.
  std::vector<Eigen::Triplet<double, std::int64_t>> outside;
  const std::int64_t* outer = t.outerIndexPtr();
  const std::int64_t* inner = t.innerIndexPtr();
  double* values = t.valuePtr();
  for (const Local& l : locals) {
    const Eigen::Index r = l.inverse.rows();
    for (Eigen::Index i = 0; i < r; ++i) {
      const Eigen::Index row_i = active[l.first + static_cast<std::size_t>(i)];
      for (Eigen::Index j = 0; j < r; ++j) {
        const double coefficient = l.inverse(i, j);
        if (coefficient == 0.0)
          continue;
        const Eigen::Index row_j = active[l.first + static_cast<std::size_t>(j)];
        for (CholmodMatrix::InnerIterator c(c_transposed_, row_j); c; ++c) {
          const std::int64_t* begin = inner + outer[c.row()];
          const std::int64_t* end = inner + outer[c.row() + 1];
          for (CholmodMatrix::InnerIterator p(*lcp_.phi, row_i); p; ++p) {
            if (p.row() < c.row())
              continue;
            const double term = p.value() * coefficient * c.value();
            const std::int64_t* at = std::lower_bound(begin, end, p.row());
            if (at != end && *at == p.row())
              values[at - inner] -= term;
            else
              outside.emplace_back(p.row(), c.row(), -term);
          }
        }
      }
    }
  }
  if (!outside.empty()) {
    CholmodMatrix extra(t.rows(), t.cols());
    extra.setFromTriplets(outside.begin(), outside.end());
    t = CholmodMatrix(t + extra);
  }
  return t;
}

ActiveSetEquations::Solution ReducedTangentEquations::solve(const std::vector<Eigen::Index>& active,
                                                            const Damping& damping, Check check) {
  std::optional<Solution> out = solve_on(active, damping, true, check);
  if (!out)
    out = solve_on(active, damping, false, check);
  return std::move(*out);
}

bool ReducedTangentEquations::hold_tangent(const std::vector<Eigen::Index>& active,
                                           const std::vector<Local>& locals, bool may_update,
                                           std::optional<TangentUpdate>& update) {
  // The terms Phi_g N_gg^-1 C_g that describe the tangent.
  std::vector<TangentTerm> terms;
  for (const Local& l : locals) {
    TangentTerm term{group(active[l.first]), {}, {}, l.block};
    for (std::size_t i = l.first; i < l.first + static_cast<std::size_t>(l.block.rows()); ++i) {
      term.modes.push_back(mode(active[i]));
      term.phi.emplace_back(lcp_.phi->col(active[i]));
    }
    terms.push_back(std::move(term));
  }
  // The kept factor, as it is or updated, else the lower triangle of K - Phi_A N_AA^-1 C_A
  // factorized.
  update = may_update ? update_from_kept(tangent_, terms, limits_) : std::nullopt;
  if (update && update->p.cols() == 0) {
    ++reused_;
  } else if (update) {
    ++updated_;
  } else {
    const CholmodMatrix& tangent = form_tangent(active, locals);
    tangent_.columns.clear();
    tangent_.terms.reset();
    if (!factorize(tangent))
      return false;
    tangent_.terms = std::move(terms);
  }
  return true;
}

std::optional<LinearSolve> ReducedTangentEquations::tangent_solve(
    const std::vector<Eigen::Index>& active) {
  const std::optional<std::vector<Local>> found = locals(active, {});
  auto update = std::make_shared<std::optional<TangentUpdate>>();
  if (!found || !hold_tangent(active, *found, true, *update))
    return std::nullopt;
  return [&tangent = tangent_, update](const Eigen::VectorXd& rhs) {
    return solve_tangent(tangent, rhs, *update ? &**update : nullptr);
  };
}

std::optional<ActiveSetEquations::Solution> ReducedTangentEquations::solve_on(
    const std::vector<Eigen::Index>& active, const Damping& damping, bool may_update, Check check) {
  Solution out = start(active);
  if (active.empty())
    return out;
  // N_AA^-1 group by group.
  const std::optional<std::vector<Local>> found = locals(active, damping);
  if (!found)
    return out;
  const std::vector<Local>& locals = *found;
  std::optional<TangentUpdate> update;
  if (!hold_tangent(active, locals, may_update, update)) {
    out.ray = mechanism(tangent_.matrix, active, locals);
    return out;
  }
  const TangentUpdate* through = update ? &*update : nullptr;
  const double worst = solve_through(
      active, locals, damping, check,
      [&](const Eigen::VectorXd& rhs) { return solve_tangent(tangent_, rhs, through); }, out);
  if (check == Check::from_solve) {
    out.regular = true;
    return out;
  }
  // A solve through an update that still misses the accuracy is done again on a factorized
  // tangent.
  if (through != nullptr && through->p.cols() > 0 && !(worst <= kSolveAccuracy))
    return std::nullopt;
  out.regular = true;
  return out;
}

}  // namespace bimrock
