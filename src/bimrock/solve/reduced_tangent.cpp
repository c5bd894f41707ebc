#include <bimrock/solve/reduced_tangent.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

#include <Eigen/Eigenvalues>
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
/// A tangent that differs from the one whose factor is kept in the terms of at most this many
/// rows may be solved through that factor (Woodbury: one back-solve per row, where a
/// factorization costs as much as K's; the capacitance matrix is dense).
constexpr Eigen::Index kMostUpdatedRows = 256;
/// The capacitance matrix of an update is singular below this relative eigenvalue (the new
/// tangent is then nearly singular: left to a factorization, which finds a mechanism).
constexpr double kSingularCapacitance = 1e-12;
/// A solve through an update must meet the active rows' equations to this relative residual
/// (the LCP asks for 1e-9), else the tangent is factorized.
constexpr double kUpdateAccuracy = 1e-10;
}  // namespace

// S_new = S_kept - P D P^T, P = [Phi of the new terms | Phi of the old terms] (n x r), D =
// diag(N_new^-1, -N_old^-1); so S_new^-1 b = y + Y Cap^-1 P^T y with y = S_kept^-1 b,
// Y = S_kept^-1 P and the capacitance Cap = D^-1 - P^T Y = V diag(lambda) V^T.
struct ReducedTangentEquations::Update {
  CholmodMatrix p;
  std::vector<const Eigen::VectorXd*> y;  // its columns, kept in kept_columns_
  Eigen::MatrixXd vectors;
  Eigen::VectorXd inverse_values;
};

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
                                                 TangentFactor& tangent, TangentUpdateLimits limits)
    : lcp_(lcp), k_(k), tangent_(tangent), c_transposed_(lcp.c->transpose()), limits_(limits) {}

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

std::optional<ReducedTangentEquations::Update> ReducedTangentEquations::update_from_kept(
    const std::vector<Term>& terms) {
  if (!kept_terms_ || !tangent_.cholesky.factorized())
    return std::nullopt;
  // The groups whose terms differ: the new term goes in, the kept one out.
  std::map<Eigen::Index, const Term*> kept;
  for (const Term& t : *kept_terms_)
    kept.emplace(group(t.rows.front()), &t);
  std::vector<const Term*> added;
  std::vector<const Term*> removed;
  for (const Term& t : terms) {
    const auto it = kept.find(group(t.rows.front()));
    if (it != kept.end()) {
      const bool same = it->second->rows == t.rows && it->second->n_local == t.n_local;
      if (!same)
        removed.push_back(it->second);
      kept.erase(it);
      if (same)
        continue;
    }
    added.push_back(&t);
  }
  for (const auto& [g, t] : kept)
    removed.push_back(t);
  Eigen::Index r = 0;
  Eigen::Index r_removed = 0;
  for (const Term* t : added)
    r += static_cast<Eigen::Index>(t->rows.size());
  for (const Term* t : removed)
    r_removed += static_cast<Eigen::Index>(t->rows.size());
  r += r_removed;
  Update u;
  const Eigen::Index n = lcp_.k_lower->rows();
  if (r == 0)
    return u;  // the same tangent
  // Worth it while the back-solves for the columns not kept cost less than half a
  // factorization (a solve: ~4 flops per non-zero of the factor), and the columns kept take
  // at most a quarter of the factor's memory (or 32 of them: a small factor is cheap).
  const double factor_entries = static_cast<double>(tangent_.cholesky.factor_nonzeros());
  const double affordable = limits_.new_columns >= 0.0
                                ? limits_.new_columns
                                : 0.5 * tangent_.cholesky.factor_flops() / (4.0 * factor_entries);
  const auto columns =
      limits_.rows >= 0
          ? static_cast<std::size_t>(limits_.rows)
          : std::max<std::size_t>(
                32, static_cast<std::size_t>(factor_entries / (4.0 * static_cast<double>(n))));
  if (r > kMostUpdatedRows || static_cast<std::size_t>(r) > columns)
    return std::nullopt;
  // P, and D^-1 = diag(N_new, -N_old) block by block.
  std::vector<Eigen::Index> p_rows;  // the row of each column of P
  Eigen::MatrixXd d_inverse = Eigen::MatrixXd::Zero(r, r);
  auto put = [&](const Term& t, double sign) {
    const auto k = static_cast<Eigen::Index>(t.rows.size());
    const auto col = static_cast<Eigen::Index>(p_rows.size());
    d_inverse.block(col, col, k, k) = sign * t.n_local;
    p_rows.insert(p_rows.end(), t.rows.begin(), t.rows.end());
  };
  for (const Term* t : added)
    put(*t, 1.0);
  for (const Term* t : removed)
    put(*t, -1.0);
  // The columns of Phi of a set of rows, as a sparse n x k matrix.
  const auto phi_of = [&](const std::vector<Eigen::Index>& rows) {
    std::vector<Eigen::Triplet<double, std::int64_t>> entries;
    for (std::size_t c = 0; c < rows.size(); ++c)
      for (CholmodMatrix::InnerIterator p(*lcp_.phi, rows[c]); p; ++p)
        entries.emplace_back(p.row(), static_cast<std::int64_t>(c), p.value());
    CholmodMatrix out(n, static_cast<Eigen::Index>(rows.size()));
    out.setFromTriplets(entries.begin(), entries.end());
    return out;
  };
  u.p = phi_of(p_rows);
  std::vector<Eigen::Index> missing;
  for (Eigen::Index row : p_rows)
    if (!kept_columns_.count(row) &&
        std::find(missing.begin(), missing.end(), row) == missing.end())
      missing.push_back(row);
  if (kept_columns_.size() + missing.size() > columns) {
    kept_columns_.clear();
    missing = p_rows;
    std::sort(missing.begin(), missing.end());
    missing.erase(std::unique(missing.begin(), missing.end()), missing.end());
  }
  if (static_cast<double>(missing.size()) > affordable)
    return std::nullopt;
  if (!missing.empty()) {
    const Eigen::MatrixXd solved = tangent_.cholesky.solve(Eigen::MatrixXd(phi_of(missing)));
    for (std::size_t c = 0; c < missing.size(); ++c)
      kept_columns_[missing[c]] = solved.col(static_cast<Eigen::Index>(c));
  }
  Eigen::MatrixXd capacitance = d_inverse;
  for (Eigen::Index c = 0; c < r; ++c) {
    u.y.push_back(&kept_columns_.at(p_rows[static_cast<std::size_t>(c)]));
    capacitance.col(c) -= u.p.transpose() * *u.y.back();
  }
  capacitance = 0.5 * (capacitance + capacitance.transpose()).eval();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(capacitance);
  if (eigen.info() != Eigen::Success)
    return std::nullopt;
  const Eigen::VectorXd& lambda = eigen.eigenvalues();
  // Inertia (Haynsworth, on [S_kept P; P^T D^-1]): S_new has as many negative eigenvalues as
  // the capacitance has beyond the r_removed of D^-1 (S_kept is positive definite). Cholesky
  // needs none, nor a nearly singular capacitance.
  const double top = lambda.cwiseAbs().maxCoeff();
  if ((lambda.array() < 0.0).count() != r_removed ||
      !(lambda.cwiseAbs().minCoeff() > kSingularCapacitance * top))
    return std::nullopt;
  u.vectors = eigen.eigenvectors();
  u.inverse_values = lambda.cwiseInverse();
  return u;
}

Eigen::VectorXd ReducedTangentEquations::solve_tangent(const Eigen::VectorXd& rhs,
                                                       const Update* update) const {
  Eigen::VectorXd y = tangent_.cholesky.solve(rhs);
  if (update != nullptr && update->p.cols() > 0) {
    const Eigen::VectorXd py = update->p.transpose() * y;
    const Eigen::VectorXd c =
        update->vectors * update->inverse_values.cwiseProduct(update->vectors.transpose() * py);
    for (std::size_t k = 0; k < update->y.size(); ++k)
      y += c(static_cast<Eigen::Index>(k)) * *update->y[k];
  }
  return y;
}

ActiveSetEquations::Solution ReducedTangentEquations::solve(const std::vector<Eigen::Index>& active,
                                                            const Damping& damping) {
  std::optional<Solution> out = solve_on(active, damping, true);
  if (!out)
    out = solve_on(active, damping, false);
  return std::move(*out);
}

std::optional<ActiveSetEquations::Solution> ReducedTangentEquations::solve_on(
    const std::vector<Eigen::Index>& active, const Damping& damping, bool may_update) {
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
  // N_AA^-1 group by group (the active rows of a group are consecutive in `active`).
  std::vector<Local> locals;
  std::vector<Term> terms;
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
    locals.push_back(Local{a, lu.inverse()});
    terms.push_back(Term{{active.begin() + static_cast<std::ptrdiff_t>(a),
                          active.begin() + static_cast<std::ptrdiff_t>(b)},
                         std::move(local)});
    a = b;
  }
  // The kept factor, as it is or updated, else the lower triangle of K - Phi_A N_AA^-1 C_A
  // factorized.
  const std::optional<Update> update =
      may_update ? update_from_kept(terms) : std::optional<Update>();
  if (update && update->p.cols() == 0) {
    ++reused_;
  } else if (update) {
    ++updated_;
  } else {
    std::vector<Eigen::Triplet<double, std::int64_t>> plastic;
    for (const Local& l : locals) {
      const Eigen::Index r = l.inverse.rows();
      for (Eigen::Index i = 0; i < r; ++i) {
        const Eigen::Index row_i = active[l.first + static_cast<std::size_t>(i)];
        for (Eigen::Index j = 0; j < r; ++j) {
          const double coefficient = l.inverse(i, j);
          if (coefficient == 0.0)
            continue;
          const Eigen::Index row_j = active[l.first + static_cast<std::size_t>(j)];
          for (CholmodMatrix::InnerIterator p(*lcp_.phi, row_i); p; ++p)
            for (CholmodMatrix::InnerIterator c(c_transposed_, row_j); c; ++c)
              if (p.row() >= c.row())
                plastic.emplace_back(p.row(), c.row(), p.value() * coefficient * c.value());
        }
      }
    }
    CholmodMatrix plastic_lower(n, n);
    plastic_lower.setFromTriplets(plastic.begin(), plastic.end());
    const CholmodMatrix tangent = *lcp_.k_lower - plastic_lower;
    kept_columns_.clear();
    if (!factorize(tangent)) {
      kept_terms_.reset();
      out.ray = mechanism(tangent, active, locals);
      return out;
    }
    kept_terms_ = std::move(terms);
  }
  const Update* through = update ? &*update : nullptr;
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
    const Eigen::VectorXd x = solve_tangent(rhs, through);
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
  if (through != nullptr && through->p.cols() > 0)
    for (Eigen::Index i : active) {
      const double residual = out.w(i) + d(i) * (out.z(i) - (damped ? damping.center(i) : 0.0));
      if (!(std::abs(residual) <= kUpdateAccuracy * out.w_scale(i)))
        return std::nullopt;
    }
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
