#include <bimrock/solve/sparse_cholesky.hpp>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

#include <bimrock/solve/sparse_cholesky_impl.hpp>

namespace bimrock {

using cholesky::block_pattern;
using cholesky::expand_blocks;
using cholesky::release;
using cholesky::view;

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// A checksum of a pattern (sums of its indices weighted by position, which vectorize, unlike
// block_ordering.cpp's fingerprint()): it tells the analyzed pattern from another passed by
// mistake.
std::uint64_t pattern_checksum(const CholmodMatrix& a) {
  std::uint64_t sum = static_cast<std::uint64_t>(a.rows());
  for (std::int64_t c = 0; c <= a.cols(); ++c)
    sum += static_cast<std::uint64_t>(a.outerIndexPtr()[c]) * static_cast<std::uint64_t>(c + 1);
  std::uint64_t rows = 0;
  for (std::int64_t k = 0; k < a.nonZeros(); ++k)
    rows += static_cast<std::uint64_t>(a.innerIndexPtr()[k]) * static_cast<std::uint64_t>(k + 1);
  return sum ^ (rows * 0x9E3779B97F4A7C15ULL);
}

}  // namespace

void SparseCholesky::analyze_given(const cholmod_sparse_struct& matrix, const std::int64_t* perm,
                                   bool exact) {
  cholmod_sparse a = matrix;
  cholmod_common& cm = impl_->common;
  const int saved_nmethods = cm.nmethods;
  const int saved_ordering = cm.method[0].ordering;
  const int saved_supernodal = cm.supernodal;
  const int saved_postorder = cm.postorder;
  cm.nmethods = 1;
  cm.method[0].ordering = perm ? CHOLMOD_GIVEN : CHOLMOD_NATURAL;
  if (exact) {
    // Supernodal, and the order kept as it is: CHOLMOD would otherwise postorder its
    // elimination tree, which may move a leading column after trailing ones.
    cm.supernodal = CHOLMOD_SUPERNODAL;
    cm.postorder = 0;
  }
  impl_->factor = cholmod_l_analyze_p(&a, const_cast<std::int64_t*>(perm), nullptr, 0, &cm);
  cm.nmethods = saved_nmethods;
  cm.method[0].ordering = saved_ordering;
  cm.supernodal = saved_supernodal;
  cm.postorder = saved_postorder;
}

void SparseCholesky::finish_analysis(const CholmodMatrix& lower) {
  if (!impl_->factor)
    throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
  impl_->factorizations_since_analysis = 0;
  impl_->analyzed_pattern = pattern_checksum(lower);
  n_ = lower.rows();
  analyzed_nonzeros_ = lower.nonZeros();
  factor_flops_ = impl_->common.fl;
  factorized_ = false;
}

void SparseCholesky::analyze(const CholmodMatrix& lower, int block_size) {
  if (!lower.isCompressed())
    throw std::logic_error("SparseCholesky: matrix must be compressed");
  if (impl_->factor)
    cholmod_l_free_factor(&impl_->factor, &impl_->common);
  impl_->release_permuted();  // not only emptied: the new pattern may be refactorized never
  order_.clear();
  level_start_.clear();
  boundary_start_.clear();
  cholmod_common& cm = impl_->common;
  if (block_size > 1 && lower.rows() % block_size == 0 && lower.rows() > block_size) {
    // Order the block graph with CHOLMOD's default strategy, expand the permutation to the
    // unknowns, and analyze the full matrix with that given ordering.
    const std::vector<std::int64_t> perm =
        expand_blocks(block_order(block_pattern(lower, block_size)), block_size);
    analyze_given(view(lower), perm.data(), false);
  } else {
    cholmod_sparse a = view(lower);
    impl_->factor = cholmod_l_analyze(&a, &cm);
  }
  finish_analysis(lower);
}

void SparseCholesky::permute_into_order(const CholmodMatrix& lower, const std::int64_t* perm) {
  Impl& m = *impl_;
  const std::int64_t* outer = lower.outerIndexPtr();
  const std::int64_t* inner = lower.innerIndexPtr();
  const auto n = static_cast<std::size_t>(n_);
  std::vector<std::int64_t> inverse(n);
  for (std::int64_t k = 0; k < n_; ++k)
    inverse[static_cast<std::size_t>(perm[k])] = k;
  // Entry k (row >= column) lands at (max(a, b), min(a, b)) in the factor's order, a and b the
  // places of its row and column; entries above the diagonal are not read, as CHOLMOD reads a
  // lower triangle (stype -1). The places are worked out again at each pass, not kept per
  // entry: the map of the largest tangent is built at the analysis's peak of memory.
  const auto visit = [&](auto&& take) {
    for (std::int64_t j = 0; j < n_; ++j) {
      const std::int64_t b = inverse[static_cast<std::size_t>(j)];
      for (std::int64_t k = outer[j]; k < outer[j + 1]; ++k)
        if (inner[k] >= j) {
          const std::int64_t a = inverse[static_cast<std::size_t>(inner[k])];
          take(k, std::max(a, b), std::min(a, b));
        }
    }
  };
  m.permuted_p.assign(n + 1, 0);
  visit([&](std::int64_t, std::int64_t, std::int64_t column) {
    ++m.permuted_p[static_cast<std::size_t>(column + 1)];
  });
  for (std::size_t c = 0; c < n; ++c)
    m.permuted_p[c + 1] += m.permuted_p[c];
  // Each column's entries, in the order met, then sorted by row within the column.
  const auto kept = static_cast<std::size_t>(m.permuted_p[n]);
  std::vector<std::int64_t> source(kept);  // the caller's entry at each place
  m.permuted_i.assign(kept, 0);
  {
    std::vector<std::int64_t> next(m.permuted_p.begin(), m.permuted_p.end() - 1);
    visit([&](std::int64_t k, std::int64_t row, std::int64_t column) {
      const auto at = static_cast<std::size_t>(next[static_cast<std::size_t>(column)]++);
      m.permuted_i[at] = row;
      source[at] = k;
    });
  }
  release(inverse);
  m.scatter.assign(static_cast<std::size_t>(lower.nonZeros()), -1);
  std::vector<std::pair<std::int64_t, std::int64_t>> column;  // (row, entry) of one column
  for (std::size_t c = 0; c < n; ++c) {
    const auto first = static_cast<std::size_t>(m.permuted_p[c]);
    const auto last = static_cast<std::size_t>(m.permuted_p[c + 1]);
    column.clear();
    for (std::size_t at = first; at < last; ++at)
      column.emplace_back(m.permuted_i[at], source[at]);
    std::sort(column.begin(), column.end());
    for (std::size_t at = first; at < last; ++at) {
      m.permuted_i[at] = column[at - first].first;
      m.scatter[static_cast<std::size_t>(column[at - first].second)] =
          static_cast<std::int64_t>(at);
    }
  }
  m.permuted_x.assign(kept, 0.0);
}

bool SparseCholesky::factorize(const CholmodMatrix& lower) {
  if (!impl_->factor)
    analyze(lower);
  Impl& m = *impl_;
  const auto start = std::chrono::steady_clock::now();
  if (!lower.isCompressed() || lower.rows() != n_ || lower.nonZeros() != analyzed_nonzeros_ ||
      pattern_checksum(lower) != m.analyzed_pattern)
    throw std::logic_error("SparseCholesky::factorize: a pattern other than the analyzed one");
  // From the second factorization of a supernodal analysis (from the first after
  // analyze_last()): the matrix in the factor's order, factorized as natural (no transposes;
  // see Impl).
  const bool prebuilt = m.factorizations_since_analysis == 0 && !m.scatter.empty();
  const bool permute =
      m.factor->is_super && m.factor->Perm && (++m.factorizations_since_analysis >= 2 || prebuilt);
  if (permute) {
    if (m.scatter.empty())
      permute_into_order(lower, static_cast<const std::int64_t*>(m.factor->Perm));
    const double* x = lower.valuePtr();
    for (std::size_t k = 0; k < m.scatter.size(); ++k)
      if (m.scatter[k] >= 0)
        m.permuted_x[static_cast<std::size_t>(m.scatter[k])] = x[k];
  }
  cholmod_sparse a = view(lower);
  if (permute) {
    a.p = m.permuted_p.data();
    a.i = m.permuted_i.data();
    a.x = m.permuted_x.data();
    a.nzmax = m.permuted_x.size();
  }
  const int ordering = m.factor->ordering;
  if (permute)
    m.factor->ordering = CHOLMOD_NATURAL;
  cholmod_l_factorize(&a, impl_->factor, &impl_->common);
  m.factor->ordering = ordering;
  if (prebuilt)  // rebuilt by a second factorization, if one comes
    m.release_permuted();
  ++work_.factorizations;
  work_.factorize_seconds += seconds_since(start);
  if (impl_->common.status == CHOLMOD_OUT_OF_MEMORY)
    throw std::runtime_error("CHOLMOD factorize: out of memory");
  const auto minor = static_cast<std::int64_t>(impl_->factor->minor);
  if (impl_->common.status == CHOLMOD_NOT_POSDEF || minor < n_) {
    const auto* perm = static_cast<const std::int64_t*>(impl_->factor->Perm);
    failed_column_ = perm ? perm[minor] : minor;
    factorized_ = false;
    return false;
  }
  // A small matrix gets a simplicial LDL' factor, which does not fail where the matrix is not
  // positive definite: its D must be checked (the reduced tangent relies on the refusal).
  const cholmod_factor* f = impl_->factor;
  if (!f->is_super && !f->is_ll) {
    const auto* p = static_cast<const std::int64_t*>(f->p);
    const auto* x = static_cast<const double*>(f->x);
    for (std::int64_t j = 0; j < n_; ++j)
      if (!(x[p[j]] > 0.0)) {
        const auto* perm = static_cast<const std::int64_t*>(f->Perm);
        failed_column_ = perm ? perm[j] : j;
        factorized_ = false;
        return false;
      }
  }
  failed_column_ = -1;
  factorized_ = true;
  return true;
}

std::int64_t SparseCholesky::factor_nonzeros() const {
  if (!impl_->factor)
    return 0;
  cholmod_factor* f = impl_->factor;
  if (f->is_super)
    return static_cast<std::int64_t>(f->xsize);
  return static_cast<std::int64_t>(f->nzmax);
}

bool SparseCholesky::supernodal() const {
  return impl_->factor && impl_->factor->is_super;
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& b) const {
  if (!factorized_)
    throw std::logic_error("SparseCholesky::solve before a successful factorize");
  cholmod_dense rhs = view(b);
  const auto start = std::chrono::steady_clock::now();
  cholmod_dense* x = cholmod_l_solve(CHOLMOD_A, impl_->factor, &rhs, &impl_->common);
  work_.solved_columns += b.cols();
  work_.solve_seconds += seconds_since(start);
  if (!x)
    throw std::runtime_error("CHOLMOD solve failed");
  Eigen::MatrixXd out =
      Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), b.rows(), b.cols());
  cholmod_l_free_dense(&x, &impl_->common);
  return out;
}

Eigen::VectorXd SparseCholesky::solve(const Eigen::VectorXd& b) const {
  if (factorized_ && impl_->factor->is_super) {
    const auto* perm = static_cast<const std::int64_t*>(impl_->factor->Perm);
    std::int64_t first = 0;
    while (first < n_ && b(perm ? perm[first] : first) == 0.0)
      ++first;
    if (first >= n_ / 4)
      return solve_from(b, first);
  }
  Eigen::MatrixXd m = b;
  return solve(m).col(0);
}

Eigen::VectorXd SparseCholesky::solve_from(const Eigen::VectorXd& b, std::int64_t first) const {
  const cholmod_factor* f = impl_->factor;
  const auto start = std::chrono::steady_clock::now();
  const auto* perm = static_cast<const std::int64_t*>(f->Perm);
  // L y = P b, supernode by supernode from the one that holds column `first`: before it, y = 0.
  // That supernode is solved from `first` on (its earlier columns' y are 0 too).
  Eigen::MatrixXd rhs_y(n_, 1);  // CHOLMOD's dense view wants a matrix
  auto y = rhs_y.col(0);
  for (std::int64_t k = 0; k < n_; ++k)
    y(k) = b(perm ? perm[k] : k);
  const auto* super = static_cast<const std::int64_t*>(f->super);
  const auto* pi = static_cast<const std::int64_t*>(f->pi);
  const auto* px = static_cast<const std::int64_t*>(f->px);
  const auto* ls = static_cast<const std::int64_t*>(f->s);
  const auto* lx = static_cast<const double*>(f->x);
  for (std::size_t sn = 0; sn < f->nsuper; ++sn) {
    const std::int64_t k1 = super[sn];
    const std::int64_t k2 = super[sn + 1];
    if (k2 <= first)
      continue;
    const std::int64_t j0 = std::max(k1, first);
    const std::int64_t nrow = pi[sn + 1] - pi[sn];
    const std::int64_t ncol = k2 - j0;
    const std::int64_t offset = j0 - k1;  // the supernode's rows start with its own columns
    const Eigen::Map<const Eigen::MatrixXd, 0, Eigen::OuterStride<>> l(
        lx + px[sn] + offset * nrow + offset, nrow - offset, ncol, Eigen::OuterStride<>(nrow));
    Eigen::VectorXd x = y.segment(j0, ncol);
    l.topRows(ncol).triangularView<Eigen::Lower>().solveInPlace(x);
    y.segment(j0, ncol) = x;
    const Eigen::VectorXd below = l.bottomRows(nrow - offset - ncol) * x;
    const std::int64_t* rows = ls + pi[sn] + offset + ncol;
    for (Eigen::Index i = 0; i < below.size(); ++i)
      y(rows[i]) -= below(i);
  }
  // L^T x' = y with CHOLMOD, then x = P^T x'.
  cholmod_dense rhs = view(rhs_y);
  cholmod_dense* xp = cholmod_l_solve(CHOLMOD_Lt, impl_->factor, &rhs, &impl_->common);
  if (!xp)
    throw std::runtime_error("CHOLMOD solve failed");
  const auto* values = static_cast<const double*>(xp->x);
  Eigen::VectorXd x(n_);
  for (std::int64_t k = 0; k < n_; ++k)
    x(perm ? perm[k] : k) = values[k];
  cholmod_l_free_dense(&xp, &impl_->common);
  ++work_.solved_columns;
  work_.solve_seconds += seconds_since(start);
  return x;
}

}  // namespace bimrock
