/// @file SparseCholesky's fill-reducing order on the graph of blocks: the unknowns of a block
/// move together, so the graph of its block_size x block_size blocks is ordered (CHOLMOD's
/// default strategy) and the order expanded to the unknowns. The order is kept for the last
/// pattern it was computed for: every new set of zones (analyze_last) reuses it.
#include <bimrock/solve/sparse_cholesky.hpp>

#include <stdexcept>
#include <vector>

#include <bimrock/solve/sparse_cholesky_impl.hpp>

namespace bimrock {

namespace cholesky {

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

// The permutation of the unknowns that orders whole blocks of block_size as `coarse` does.
std::vector<std::int64_t> expand_blocks(const std::vector<std::int64_t>& coarse, int block_size) {
  std::vector<std::int64_t> perm(coarse.size() * static_cast<std::size_t>(block_size));
  for (std::size_t k = 0; k < coarse.size(); ++k)
    for (int d = 0; d < block_size; ++d)
      perm[block_size * k + d] = block_size * coarse[k] + d;
  return perm;
}

}  // namespace cholesky

namespace {

// The ordering CHOLMOD's default strategy gives a symmetric pattern (lower triangle).
std::vector<std::int64_t> default_ordering(const CholmodMatrix& pattern, cholmod_common& cm) {
  cholmod_sparse p = cholesky::view(pattern);
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

}  // namespace

const std::vector<std::int64_t>& SparseCholesky::block_order(const CholmodMatrix& pattern) {
  const std::uint64_t key = fingerprint(pattern);
  if (block_order_.empty() || key != block_order_key_) {
    block_order_ = default_ordering(pattern, impl_->common);
    block_order_key_ = key;
  }
  return block_order_;
}

}  // namespace bimrock
