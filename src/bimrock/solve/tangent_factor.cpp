#include <bimrock/solve/tangent_factor.hpp>

#include <algorithm>
#include <cstddef>

#include <Eigen/Eigenvalues>

namespace bimrock {

namespace {
/// A tangent that differs from the one whose factor is kept in the terms of at most this many
/// rows may be solved through that factor (Woodbury: one back-solve per row, where a
/// factorization costs as much as K's; the capacitance matrix is dense).
constexpr Eigen::Index kMostUpdatedRows = 256;
/// The capacitance matrix of an update is singular below this relative eigenvalue (the new
/// tangent is then nearly singular: left to a factorization, which finds a mechanism).
constexpr double kSingularCapacitance = 1e-12;
/// Right-hand sides solved together (see solve_in_chunks).
constexpr Eigen::Index kSolveChunk = 32;

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

std::optional<TangentUpdate> update_from_kept(TangentFactor& tangent,
                                              const std::vector<TangentTerm>& terms,
                                              TangentUpdateLimits limits) {
  if (!tangent.terms || !tangent.cholesky.factorized())
    return std::nullopt;
  // The groups whose terms differ: the new term goes in, the kept one out.
  std::map<Eigen::Index, const TangentTerm*> kept;
  for (const TangentTerm& t : *tangent.terms)
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
  TangentUpdate u;
  const Eigen::Index n = tangent.cholesky.rows();
  if (r == 0)
    return u;  // the same tangent
  // Worth it while the back-solves for the columns not kept cost less than half a factorization
  // in CHOLMOD's flop count (a solve: ~4 flops per non-zero of the factor), and the columns
  // kept take at most a quarter of the factor's memory (or 32 of them: a small factor is
  // cheap). Larger budgets trade factorizations for more tangent solves, smaller ones the
  // reverse: in the analysis a new column costs more than its flop count says (few columns per
  // update solve less well together).
  const double factor_entries = static_cast<double>(tangent.cholesky.factor_nonzeros());
  const double affordable = limits.new_columns >= 0.0
                                ? limits.new_columns
                                : 0.5 * tangent.cholesky.factor_flops() / (4.0 * factor_entries);
  const auto columns =
      limits.rows >= 0
          ? static_cast<std::size_t>(limits.rows)
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
  auto& kept_columns = tangent.columns;
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
    const Eigen::MatrixXd solved = solve_in_chunks(tangent.cholesky, columns_of(missing));
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

Eigen::VectorXd solve_tangent(const TangentFactor& tangent, const Eigen::VectorXd& rhs,
                              const TangentUpdate* update) {
  Eigen::VectorXd y = tangent.cholesky.solve(rhs);
  if (update != nullptr && update->p.cols() > 0) {
    const Eigen::VectorXd py = update->p.transpose() * y;
    const Eigen::VectorXd c =
        update->vectors * update->inverse_values.cwiseProduct(update->vectors.transpose() * py);
    for (std::size_t k = 0; k < update->y.size(); ++k)
      y += c(static_cast<Eigen::Index>(k)) * *update->y[k];
  }
  return y;
}

}  // namespace bimrock
