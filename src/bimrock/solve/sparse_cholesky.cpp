#include <bimrock/solve/sparse_cholesky.hpp>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <cholmod.h>

#include <bimrock/solve/factor_memory.hpp>

namespace bimrock {

namespace {

// Frees a vector's memory (`v = {}` keeps its capacity: it assigns an empty initializer list).
template <class Vector>
void release(Vector& v) {
  Vector().swap(v);
}

// A cholmod view of the Eigen matrix (no copy): stype -1 reads the lower triangle.
cholmod_sparse view(const CholmodMatrix& a) {
  cholmod_sparse s{};
  s.nrow = static_cast<size_t>(a.rows());
  s.ncol = static_cast<size_t>(a.cols());
  s.nzmax = static_cast<size_t>(a.nonZeros());
  s.p = const_cast<std::int64_t*>(a.outerIndexPtr());
  s.i = const_cast<std::int64_t*>(a.innerIndexPtr());
  s.x = const_cast<double*>(a.valuePtr());
  s.stype = -1;
  s.itype = CHOLMOD_LONG;
  s.xtype = CHOLMOD_REAL;
  s.dtype = CHOLMOD_DOUBLE;
  s.sorted = 1;
  s.packed = 1;
  return s;
}

cholmod_dense view(const Eigen::MatrixXd& b) {
  cholmod_dense d{};
  d.nrow = static_cast<size_t>(b.rows());
  d.ncol = static_cast<size_t>(b.cols());
  d.nzmax = d.nrow * d.ncol;
  d.d = d.nrow;
  d.x = const_cast<double*>(b.data());
  d.xtype = CHOLMOD_REAL;
  d.dtype = CHOLMOD_DOUBLE;
  return d;
}

}  // namespace

struct SparseCholesky::Impl {
  cholmod_common common{};
  cholmod_factor* factor = nullptr;
  // A supernodal factor in a fill-reducing order takes tril(P A P^T); from a lower triangle
  // CHOLMOD builds it with two transposes per factorization (cholmod_factorize_p), a sizeable
  // part of a factorization's time on the main thread.
  // From the second factorization of one analysis on, the matrix is scattered into that form
  // here, in one pass, and factorized as if its order were natural.
  std::int64_t factorizations_since_analysis = 0;
  // analyze_last() builds that form at once and analyzes it in natural order: the analysis
  // costs the same (CHOLMOD's four transposes give way to the permutation), and the first
  // factorization reads it without CHOLMOD's transposes, then frees it (K and a region's S are
  // factorized once per analysis).
  std::vector<std::int64_t> permuted_p;  // tril(P A P^T): column starts, rows, values
  std::vector<std::int64_t> permuted_i;
  std::vector<double> permuted_x;
  std::vector<std::int64_t> scatter;  // entry k of the caller's lower -> permuted_x (-1: above)
  // The analyzed pattern's checksum: a matrix of another one is refused (CHOLMOD would
  // factorize it without notice, into a wrong factor).
  std::uint64_t analyzed_pattern = 0;

  void release_permuted() {
    release(scatter);
    release(permuted_p);
    release(permuted_i);
    release(permuted_x);
  }

  Impl() {
    install_factor_memory();  // before CHOLMOD's first block
    cholmod_l_start(&common);
    common.print = 0;  // we report failures ourselves
  }
  ~Impl() {
    if (factor)
      cholmod_l_free_factor(&factor, &common);
    cholmod_l_finish(&common);
  }
};

SparseCholesky::SparseCholesky() : impl_(std::make_unique<Impl>()) {}
SparseCholesky::~SparseCholesky() = default;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The lower-triangular pattern of the graph of block_size x block_size blocks of `lower`.
CholmodMatrix block_pattern(const CholmodMatrix& lower, int block_size) {
  const std::int64_t nb = lower.rows() / block_size;
  std::vector<Eigen::Triplet<double, std::int64_t>> entries;
  std::vector<std::int64_t> seen(static_cast<std::size_t>(nb), -1);
  for (std::int64_t kb = 0; kb < nb; ++kb) {
    for (std::int64_t c = kb * block_size; c < (kb + 1) * block_size; ++c) {
      for (CholmodMatrix::InnerIterator it(lower, c); it; ++it) {
        const std::int64_t rb = it.row() / block_size;
        if (rb >= kb && seen[rb] != kb) {
          seen[rb] = kb;
          entries.emplace_back(rb, kb, 1.0);
        }
      }
    }
  }
  CholmodMatrix pattern(nb, nb);
  pattern.setFromTriplets(entries.begin(), entries.end());
  pattern.makeCompressed();
  return pattern;
}

// The ordering CHOLMOD's default strategy gives a symmetric pattern (lower triangle).
std::vector<std::int64_t> default_ordering(const CholmodMatrix& pattern, cholmod_common& cm) {
  cholmod_sparse p = view(pattern);
  cholmod_factor* f = cholmod_l_analyze(&p, &cm);
  if (!f)
    throw std::runtime_error("CHOLMOD analyze failed (out of memory?)");
  const auto* perm = static_cast<const std::int64_t*>(f->Perm);
  std::vector<std::int64_t> out(perm, perm + pattern.rows());
  cholmod_l_free_factor(&f, &cm);
  return out;
}

// A fingerprint of a pattern (FNV-1a over its column starts and row indices): whether a cached
// ordering was computed for this very graph.
std::uint64_t fingerprint(const CholmodMatrix& pattern) {
  std::uint64_t h = 1469598103934665603ULL;
  auto mix = [&h](std::int64_t v) {
    h ^= static_cast<std::uint64_t>(v);
    h *= 1099511628211ULL;
  };
  mix(pattern.rows());
  for (std::int64_t c = 0; c <= pattern.cols(); ++c)
    mix(pattern.outerIndexPtr()[c]);
  for (std::int64_t k = 0; k < pattern.nonZeros(); ++k)
    mix(pattern.innerIndexPtr()[k]);
  return h;
}

// A checksum of a pattern (sums of its indices weighted by position, which vectorize, unlike
// fingerprint()): it tells the analyzed pattern from another passed by mistake.
std::uint64_t pattern_checksum(const CholmodMatrix& a) {
  std::uint64_t sum = static_cast<std::uint64_t>(a.rows());
  for (std::int64_t c = 0; c <= a.cols(); ++c)
    sum += static_cast<std::uint64_t>(a.outerIndexPtr()[c]) * static_cast<std::uint64_t>(c + 1);
  std::uint64_t rows = 0;
  for (std::int64_t k = 0; k < a.nonZeros(); ++k)
    rows += static_cast<std::uint64_t>(a.innerIndexPtr()[k]) * static_cast<std::uint64_t>(k + 1);
  return sum ^ (rows * 0x9E3779B97F4A7C15ULL);
}

// The permutation of the unknowns that orders whole blocks of block_size as `coarse` does.
std::vector<std::int64_t> expand_blocks(const std::vector<std::int64_t>& coarse, int block_size) {
  std::vector<std::int64_t> perm(coarse.size() * static_cast<std::size_t>(block_size));
  for (std::size_t k = 0; k < coarse.size(); ++k)
    for (int d = 0; d < block_size; ++d)
      perm[block_size * k + d] = block_size * coarse[k] + d;
  return perm;
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

const std::vector<std::int64_t>& SparseCholesky::block_order(const CholmodMatrix& pattern) {
  const std::uint64_t key = fingerprint(pattern);
  if (block_order_.empty() || key != block_order_key_) {
    block_order_ = default_ordering(pattern, impl_->common);
    block_order_key_ = key;
  }
  return block_order_;
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

void SparseCholesky::analyze_last(const CholmodMatrix& lower, int block_size,
                                  const std::vector<char>& level) {
  if (!lower.isCompressed())
    throw std::logic_error("SparseCholesky: matrix must be compressed");
  if (block_size < 1 || lower.rows() % block_size != 0 ||
      static_cast<std::int64_t>(level.size()) != lower.rows() / block_size)
    throw std::logic_error("SparseCholesky::analyze_last: one level per block");
  if (impl_->factor)
    cholmod_l_free_factor(&impl_->factor, &impl_->common);
  impl_->release_permuted();
  const CholmodMatrix pattern = block_pattern(lower, block_size);
  const std::int64_t nb = pattern.rows();
  const int top = nb > 0 ? *std::max_element(level.begin(), level.end()) : 0;
  std::vector<char> coupled(static_cast<std::size_t>(nb), 0);  // next to a lower level
  for (std::int64_t c = 0; c < nb; ++c)
    for (CholmodMatrix::InnerIterator it(pattern, c); it; ++it) {
      const char a = level[static_cast<std::size_t>(c)];
      const char b = level[static_cast<std::size_t>(it.row())];
      if (a == b)
        continue;
      if (std::abs(a - b) > 1)
        throw std::logic_error("SparseCholesky::analyze_last: zones that do not nest");
      coupled[static_cast<std::size_t>(a > b ? c : it.row())] = 1;
    }
  // Groups: level 0; then per level its blocks coupled to no lower one, then those coupled to
  // one. Each group keeps the relative order of the whole graph's own fill-reducing order: its
  // separators, restricted to a group, still separate it once the higher levels come last.
  // Ordering each group on its own graph instead would cut the ring-shaped groups anew and
  // ignore their fill into the zones ordered after them: more flops in every condensation.
  std::vector<std::vector<std::int64_t>> groups(static_cast<std::size_t>(2 * top + 1));
  for (std::int64_t b : block_order(pattern)) {
    const auto i = static_cast<std::size_t>(b);
    const int l = level[i];
    if (l < 0)
      throw std::logic_error("SparseCholesky::analyze_last: a negative level");
    groups[l == 0 ? 0 : static_cast<std::size_t>(2 * l - 1 + coupled[i])].push_back(b);
  }
  std::vector<std::int64_t> coarse;
  level_start_.assign(static_cast<std::size_t>(top + 1), 0);
  boundary_start_.assign(static_cast<std::size_t>(top + 1), 0);
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const auto position = static_cast<std::int64_t>(block_size * coarse.size());
    if (g > 0 && g % 2 == 1)
      level_start_[(g + 1) / 2] = position;
    else if (g > 0)
      boundary_start_[g / 2] = position;
    coarse.insert(coarse.end(), groups[g].begin(), groups[g].end());
  }
  order_ = expand_blocks(coarse, block_size);
  n_ = lower.rows();
  Impl& m = *impl_;
  permute_into_order(lower, order_.data());  // analyzed as natural (see Impl)
  cholmod_sparse permuted = view(lower);
  permuted.p = m.permuted_p.data();
  permuted.i = m.permuted_i.data();
  permuted.x = m.permuted_x.data();
  permuted.nzmax = m.permuted_x.size();
  analyze_given(permuted, nullptr, true);
  finish_analysis(lower);
  // The factor of tril(P A P^T) in natural order is that of A in the order P: it says so.
  std::copy(order_.begin(), order_.end(), static_cast<std::int64_t*>(m.factor->Perm));
  m.factor->ordering = CHOLMOD_GIVEN;
}

std::vector<std::int64_t> SparseCholesky::trailing_unknowns(int level) const {
  if (level < 1 || level > levels())
    return {};
  return {order_.begin() + level_start_[static_cast<std::size_t>(level)], order_.end()};
}

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
