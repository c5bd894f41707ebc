/// @file A zone's Schur complement read from the trailing block of SparseCholesky's supernodal
/// factor after analyze_last: with P the zone's unknowns, L_PP L_PP^T = S = K_PP - K_PE K_EE^-1
/// K_EP. schur_complement() forms S (it differs from K_PP only on the zone's boundary),
/// solve_trailing() solves with it through L_PP without forming it, trailing_nonzeros() says
/// L_PP's size.
#include <bimrock/solve/sparse_cholesky.hpp>

#include <algorithm>
#include <stdexcept>
#include <vector>

#include <bimrock/solve/sparse_cholesky_impl.hpp>

namespace bimrock {

CholmodMatrix SparseCholesky::schur_complement(const CholmodMatrix& lower, int level) const {
  const cholmod_factor* f = impl_->factor;
  if (!factorized_ || level < 1 || level > levels() || !f->is_super)
    throw std::logic_error("SparseCholesky::schur_complement before analyze_last and factorize");
  const auto l = static_cast<std::size_t>(level);
  const std::int64_t first = level_start_[l];  // of the zone's columns, in the factor's order
  const std::int64_t np = n_ - first;
  // Its unknowns coupled to lower levels: the set B, at the end of the level's own.
  const std::int64_t b0 = boundary_start_[l];
  const std::int64_t b1 = l + 1 < level_start_.size() ? level_start_[l + 1] : n_;
  const std::int64_t nb = b1 - b0;
  // S = K_PP - K_PE K_EE^-1 K_EP differs from K_PP only where both unknowns are in B, and there
  // S = L_B L_B^T over the rows B of L's columns in P (L_PP L_PP^T = S): a sum over the
  // supernodes of G G^T, G the dense rows of B of each (a supernode's rows ascend). Columns
  // after B have no row in B.
  Eigen::MatrixXd s_bb = Eigen::MatrixXd::Zero(nb, nb);
  const auto* super = static_cast<const std::int64_t*>(f->super);
  const auto* pi = static_cast<const std::int64_t*>(f->pi);
  const auto* px = static_cast<const std::int64_t*>(f->px);
  const auto* ls = static_cast<const std::int64_t*>(f->s);
  const auto* lx = static_cast<const double*>(f->x);
  for (std::size_t sn = 0; sn < f->nsuper && nb > 0; ++sn) {
    const std::int64_t k1 = super[sn];
    const std::int64_t k2 = std::min(super[sn + 1], b1);
    if (k2 <= first)
      continue;
    if (k1 >= b1)
      break;
    const std::int64_t j0 = std::max(k1, first);
    const std::int64_t nrow = pi[sn + 1] - pi[sn];
    const std::int64_t* rows = ls + pi[sn];
    if (!std::is_sorted(rows, rows + nrow))
      throw std::logic_error("SparseCholesky::schur_complement: unsorted supernode");
    const std::int64_t i0 = std::lower_bound(rows, rows + nrow, b0) - rows;
    const std::int64_t i1 = std::lower_bound(rows, rows + nrow, b1) - rows;
    if (i0 == i1)
      continue;
    const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> block(
        lx + px[sn] + (j0 - k1) * nrow + i0, i1 - i0, k2 - j0, Eigen::OuterStride<>(nrow));
    Eigen::MatrixXd g = block;
    for (Eigen::Index c = 0; c < g.cols(); ++c)  // the diagonal block's upper part is not L's
      for (Eigen::Index r = 0; r < g.rows() && rows[i0 + r] < j0 + c; ++r)
        g(r, c) = 0.0;
    // Rows that are consecutive unknowns of B (most of them: B's own dense part) are updated in
    // place; others through a product of their own, scattered.
    const std::int64_t r0 = rows[i0] - b0;
    if (rows[i1 - 1] - rows[i0] == i1 - i0 - 1) {
      s_bb.block(r0, r0, g.rows(), g.rows()).selfadjointView<Eigen::Lower>().rankUpdate(g);
      continue;
    }
    Eigen::MatrixXd h = Eigen::MatrixXd::Zero(g.rows(), g.rows());
    h.selfadjointView<Eigen::Lower>().rankUpdate(g);
    for (Eigen::Index c = 0; c < h.cols(); ++c)
      for (Eigen::Index r = c; r < h.rows(); ++r)
        s_bb(rows[i0 + r] - b0, rows[i0 + c] - b0) += h(r, c);
  }
  // K_PP elsewhere, read from K in the trailing order.
  std::vector<std::int64_t> local(static_cast<std::size_t>(n_), -1);
  for (std::int64_t k = 0; k < np; ++k)
    local[static_cast<std::size_t>(order_[static_cast<std::size_t>(first + k)])] = k;
  const std::int64_t lb0 = b0 - first;  // B in S's numbering
  const std::int64_t lb1 = b1 - first;
  const auto in_b = [&](std::int64_t k) { return k >= lb0 && k < lb1; };
  std::vector<Eigen::Triplet<double, std::int64_t>> entries;
  for (std::int64_t k = 0; k < np; ++k) {
    const std::int64_t c = order_[static_cast<std::size_t>(first + k)];
    for (CholmodMatrix::InnerIterator it(lower, c); it; ++it) {
      const std::int64_t r = local[static_cast<std::size_t>(it.row())];
      if (r < 0 || (in_b(r) && in_b(k)))
        continue;
      entries.emplace_back(std::max(r, k), std::min(r, k), it.value());
    }
  }
  for (std::int64_t c = 0; c < nb; ++c)
    for (std::int64_t r = c; r < nb; ++r)
      entries.emplace_back(lb0 + r, lb0 + c, s_bb(r, c));
  CholmodMatrix s(np, np);
  s.setFromTriplets(entries.begin(), entries.end());
  s.makeCompressed();
  return s;
}

Eigen::MatrixXd SparseCholesky::solve_trailing(const Eigen::MatrixXd& b, int level) const {
  const cholmod_factor* f = impl_->factor;
  if (!factorized_ || level < 1 || level > levels() || !f->is_super)
    throw std::logic_error("SparseCholesky::solve_trailing before analyze_last and factorize");
  const std::int64_t first = level_start_[static_cast<std::size_t>(level)];
  if (b.rows() != n_ - first)
    throw std::logic_error("SparseCholesky::solve_trailing: b is not of the zone's size");
  const auto* super = static_cast<const std::int64_t*>(f->super);
  const auto* pi = static_cast<const std::int64_t*>(f->pi);
  const auto* px = static_cast<const std::int64_t*>(f->px);
  const auto* ls = static_cast<const std::int64_t*>(f->s);
  const auto* lx = static_cast<const double*>(f->x);
  // The supernodes that hold the zone's columns: each from its first column in the zone on
  // (analyze_last keeps the order given, so every row of those columns is in the zone too).
  std::size_t from = 0;
  while (from < f->nsuper && super[from + 1] <= first)
    ++from;
  struct Part {
    Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> l;  // its columns, then below
    std::int64_t column;                                           // the first, in the zone
    std::int64_t ncol;
    const std::int64_t* below;  // the rows under its diagonal block, in the factor's order
  };
  const auto part = [&](std::size_t sn) {
    const std::int64_t j0 = std::max(super[sn], first);
    const std::int64_t offset = j0 - super[sn];
    const std::int64_t nrow = pi[sn + 1] - pi[sn];
    const std::int64_t ncol = super[sn + 1] - j0;
    return Part{
        {lx + px[sn] + offset * nrow + offset, nrow - offset, ncol, Eigen::OuterStride<>(nrow)},
        j0 - first,
        ncol,
        ls + pi[sn] + offset + ncol};
  };
  Eigen::Index widest = 0;  // rows under a diagonal block, at most
  for (std::size_t sn = from; sn < f->nsuper; ++sn)
    widest = std::max(widest, part(sn).l.rows() - part(sn).ncol);
  // Forward (L_PP y = b) then backward (L_PP^T x = y), supernode by supernode, on x in place:
  // one vector (Eigen's matrix-vector kernels), or rows of several (row-major: the rows a
  // supernode updates are scattered, and each is then contiguous).
  const auto sweep = [&](auto& x, auto& buffer) {
    for (std::size_t sn = from; sn < f->nsuper; ++sn) {
      const Part p = part(sn);
      const Eigen::Index nbelow = p.l.rows() - p.ncol;
      auto head = x.middleRows(p.column, p.ncol);
      p.l.topRows(p.ncol).template triangularView<Eigen::Lower>().solveInPlace(head);
      auto under = buffer.topRows(nbelow);
      under.noalias() = p.l.bottomRows(nbelow) * head;
      for (Eigen::Index i = 0; i < nbelow; ++i)
        x.row(p.below[i] - first) -= under.row(i);
    }
    for (std::size_t sn = f->nsuper; sn-- > from;) {
      const Part p = part(sn);
      const Eigen::Index nbelow = p.l.rows() - p.ncol;
      auto known = buffer.topRows(nbelow);
      for (Eigen::Index i = 0; i < nbelow; ++i)
        known.row(i) = x.row(p.below[i] - first);
      auto head = x.middleRows(p.column, p.ncol);
      head.noalias() -= p.l.bottomRows(nbelow).transpose() * known;
      p.l.topRows(p.ncol).template triangularView<Eigen::Lower>().transpose().solveInPlace(head);
    }
  };
  if (b.cols() == 1) {
    Eigen::VectorXd x = b.col(0);
    Eigen::VectorXd buffer(widest);
    sweep(x, buffer);
    return x;
  }
  using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;
  RowMajor x = b;
  RowMajor buffer(widest, x.cols());
  sweep(x, buffer);
  return x;
}

std::int64_t SparseCholesky::trailing_nonzeros(int level) const {
  const cholmod_factor* f = impl_->factor;
  if (!f || level < 1 || level > levels() || !f->is_super)
    return 0;
  const std::int64_t first = level_start_[static_cast<std::size_t>(level)];
  const auto* super = static_cast<const std::int64_t*>(f->super);
  const auto* pi = static_cast<const std::int64_t*>(f->pi);
  std::int64_t count = 0;
  for (std::size_t sn = 0; sn < f->nsuper; ++sn)
    if (super[sn + 1] > first) {
      const std::int64_t offset = std::max(super[sn], first) - super[sn];
      count += (pi[sn + 1] - pi[sn] - offset) * (super[sn + 1] - super[sn] - offset);
    }
  return count;
}

}  // namespace bimrock
