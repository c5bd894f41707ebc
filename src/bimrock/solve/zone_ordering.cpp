/// @file SparseCholesky's order by nested zones (analyze_last): the blocks of level 0 first,
/// each higher level after them, so that the Schur complement onto a zone is the trailing part
/// of the factor (zone_schur_complement.cpp). Within each level, its blocks coupled to a lower
/// one come last, in the relative order of the whole block graph's fill-reducing order.
#include <bimrock/solve/sparse_cholesky.hpp>

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <vector>

#include <bimrock/solve/sparse_cholesky_impl.hpp>

namespace bimrock {

using cholesky::block_pattern;
using cholesky::expand_blocks;
using cholesky::view;

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

}  // namespace bimrock
