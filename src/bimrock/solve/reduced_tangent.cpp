#include <bimrock/solve/reduced_tangent.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

#include <Eigen/Eigenvalues>
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
/// A tangent that differs from the one whose factor is kept in the terms of at most this many
/// rows may be solved through that factor (Woodbury: one back-solve per row, where a
/// factorization costs as much as K's; the capacitance matrix is dense).
constexpr Eigen::Index kMostUpdatedRows = 256;
/// The capacitance matrix of an update is singular below this relative eigenvalue (the new
/// tangent is then nearly singular: left to a factorization, which finds a mechanism).
constexpr double kSingularCapacitance = 1e-12;
/// Right-hand sides solved together (see solve_in_chunks).
constexpr Eigen::Index kSolveChunk = 32;
}  // namespace

// S_new = S_kept - P D P^T, P = [Phi of the new terms | Phi of the old terms] (n x r), D =
// diag(N_new^-1, -N_old^-1); so S_new^-1 b = y + Y Cap^-1 P^T y with y = S_kept^-1 b,
// Y = S_kept^-1 P and the capacitance Cap = D^-1 - P^T Y = V diag(lambda) V^T.
struct ReducedTangentEquations::Update {
  CholmodMatrix p;
  std::vector<const Eigen::VectorXd*> y;  // S_kept^-1 P, in TangentFactor::columns or `own`
  std::vector<Eigen::VectorXd> own;
  Eigen::MatrixXd vectors;
  Eigen::VectorXd inverse_values;
};

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

namespace {

// S^-1 B, kSolveChunk columns at a time: a solve reads the whole factor once whatever the
// number of its columns, but past a few dozen the right-hand sides fall out of cache (the
// bench's BM_SolveColumns measures a column's cost by their number).
Eigen::MatrixXd solve_in_chunks(const SparseCholesky& s, const CholmodMatrix& b) {
  Eigen::MatrixXd out(b.rows(), b.cols());
  for (Eigen::Index c = 0; c < b.cols(); c += kSolveChunk) {
    const Eigen::Index k = std::min<Eigen::Index>(kSolveChunk, b.cols() - c);
    out.middleCols(c, k) = s.solve(Eigen::MatrixXd(b.middleCols(c, k)));
  }
  return out;
}

bool same_column(const SparseColumn& a, const SparseColumn& b) {
  return a.nonZeros() == b.nonZeros() &&
         std::equal(a.innerIndexPtr(), a.innerIndexPtr() + a.nonZeros(), b.innerIndexPtr()) &&
         std::equal(a.valuePtr(), a.valuePtr() + a.nonZeros(), b.valuePtr());
}

bool same_term(const TangentTerm& a, const TangentTerm& b) {
  if (a.group != b.group || a.modes != b.modes || a.n_local != b.n_local)
    return false;
  for (std::size_t i = 0; i < a.phi.size(); ++i)
    if (!same_column(a.phi[i], b.phi[i]))
      return false;
  return true;
}

}  // namespace

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

std::optional<ReducedTangentEquations::Update> ReducedTangentEquations::update_from_kept(
    const std::vector<TangentTerm>& terms) {
  if (!tangent_.terms || !tangent_.cholesky.factorized())
    return std::nullopt;
  // The groups whose terms differ: the new term goes in, the kept one out.
  std::map<Eigen::Index, const TangentTerm*> kept;
  for (const TangentTerm& t : *tangent_.terms)
    kept.emplace(t.group, &t);
  std::vector<const TangentTerm*> added;
  std::vector<const TangentTerm*> removed;
  for (const TangentTerm& t : terms) {
    const auto it = kept.find(t.group);
    if (it != kept.end()) {
      const bool same = same_term(*it->second, t);
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
  for (const TangentTerm* t : added)
    r += static_cast<Eigen::Index>(t->modes.size());
  for (const TangentTerm* t : removed)
    r_removed += static_cast<Eigen::Index>(t->modes.size());
  r += r_removed;
  Update u;
  const Eigen::Index n = lcp_.k_lower->rows();
  if (r == 0)
    return u;  // the same tangent
  // Worth it while the back-solves for the columns not kept cost less than half a factorization
  // in CHOLMOD's flop count (a solve: ~4 flops per non-zero of the factor), and the columns
  // kept take at most a quarter of the factor's memory (or 32 of them: a small factor is
  // cheap). Larger budgets trade factorizations for more tangent solves, smaller ones the
  // reverse: in the analysis a new column costs more than its flop count says (few columns per
  // update solve less well together).
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
  // P, and D^-1 = diag(N_new, -N_old) block by block; each column of P keyed by its group and
  // mode.
  std::vector<std::pair<Eigen::Index, int>> p_keys;
  std::vector<const SparseColumn*> p_columns;
  Eigen::MatrixXd d_inverse = Eigen::MatrixXd::Zero(r, r);
  auto put = [&](const TangentTerm& t, double sign) {
    const auto k = static_cast<Eigen::Index>(t.modes.size());
    const auto col = static_cast<Eigen::Index>(p_keys.size());
    d_inverse.block(col, col, k, k) = sign * t.n_local;
    for (std::size_t i = 0; i < t.modes.size(); ++i) {
      p_keys.emplace_back(t.group, t.modes[i]);
      p_columns.push_back(&t.phi[i]);
    }
  };
  for (const TangentTerm* t : added)
    put(*t, 1.0);
  for (const TangentTerm* t : removed)
    put(*t, -1.0);
  // Columns of P: sparse n x k.
  const auto columns_of = [&](const std::vector<std::size_t>& which) {
    std::vector<Eigen::Triplet<double, std::int64_t>> entries;
    for (std::size_t c = 0; c < which.size(); ++c)
      for (SparseColumn::InnerIterator p(*p_columns[which[c]]); p; ++p)
        entries.emplace_back(p.index(), static_cast<std::int64_t>(c), p.value());
    CholmodMatrix out(n, static_cast<Eigen::Index>(which.size()));
    out.setFromTriplets(entries.begin(), entries.end());
    return out;
  };
  std::vector<std::size_t> all(p_keys.size());
  for (std::size_t c = 0; c < all.size(); ++c)
    all[c] = c;
  u.p = columns_of(all);
  // The columns of P not kept, or kept for another phi (the group's linearization moved). A
  // key is in P at most twice: a group's old and new terms, which differ.
  auto& kept_columns = tangent_.columns;
  std::vector<std::size_t> missing;
  for (std::size_t c = 0; c < p_keys.size(); ++c) {
    const auto it = kept_columns.find(p_keys[c]);
    if (it != kept_columns.end() && same_column(it->second.phi, *p_columns[c]))
      continue;
    missing.push_back(c);
  }
  if (kept_columns.size() + missing.size() > columns) {
    kept_columns.clear();
    missing = all;
  }
  if (static_cast<double>(missing.size()) > affordable)
    return std::nullopt;
  u.y.assign(p_keys.size(), nullptr);
  if (!missing.empty()) {
    const Eigen::MatrixXd solved = solve_in_chunks(tangent_.cholesky, columns_of(missing));
    u.own.reserve(missing.size());  // u.y points into it
    for (std::size_t k = 0; k < missing.size(); ++k) {
      const std::size_t c = missing[k];
      // A group's old and new terms share a key: such a column is held by the update only,
      // so that no column another one points to is overwritten.
      if (std::count(p_keys.begin(), p_keys.end(), p_keys[c]) > 1) {
        u.own.push_back(solved.col(static_cast<Eigen::Index>(k)));
        u.y[c] = &u.own.back();
      } else {
        TangentFactor::Column& kept_column = kept_columns[p_keys[c]];
        kept_column = {*p_columns[c], solved.col(static_cast<Eigen::Index>(k))};
        u.y[c] = &kept_column.solved;
      }
    }
  }
  for (std::size_t c = 0; c < p_keys.size(); ++c)
    if (u.y[c] == nullptr)
      u.y[c] = &kept_columns.at(p_keys[c]).solved;
  Eigen::MatrixXd capacitance = d_inverse;
  for (Eigen::Index c = 0; c < r; ++c)
    capacitance.col(c) -= u.p.transpose() * *u.y[static_cast<std::size_t>(c)];
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
                                                            const Damping& damping, Check check) {
  std::optional<Solution> out = solve_on(active, damping, true, check);
  if (!out)
    out = solve_on(active, damping, false, check);
  return std::move(*out);
}

std::optional<ActiveSetEquations::Solution> ReducedTangentEquations::solve_on(
    const std::vector<Eigen::Index>& active, const Damping& damping, bool may_update, Check check) {
  Solution out = start(active);
  if (active.empty())
    return out;
  // N_AA^-1 group by group, and the terms Phi_g N_gg^-1 C_g that describe the tangent.
  const std::optional<std::vector<Local>> found = locals(active, damping);
  if (!found)
    return out;
  const std::vector<Local>& locals = *found;
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
  const std::optional<Update> update =
      may_update ? update_from_kept(terms) : std::optional<Update>();
  if (update && update->p.cols() == 0) {
    ++reused_;
  } else if (update) {
    ++updated_;
  } else {
    const CholmodMatrix& tangent = form_tangent(active, locals);
    tangent_.columns.clear();
    tangent_.terms.reset();
    if (!factorize(tangent)) {
      out.ray = mechanism(tangent, active, locals);
      return out;
    }
    tangent_.terms = std::move(terms);
  }
  const Update* through = update ? &*update : nullptr;
  const double worst = solve_through(
      active, locals, damping, check,
      [&](const Eigen::VectorXd& rhs) { return solve_tangent(rhs, through); }, out);
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
