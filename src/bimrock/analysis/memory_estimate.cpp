#include <bimrock/analysis/memory_estimate.hpp>

#include <algorithm>
#include <utility>
#include <vector>

#include <cholmod.h>

#include <bimrock/analysis/memory_probe.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>

namespace bimrock {

MemoryEstimate estimate_memory(const Model& model) {
  MemoryEstimate e;
  e.now_bytes = static_cast<double>(current_memory_bytes());
  const std::int64_t nb = model.n_blocks();
  // The block graph: a block's 6 unknowns couple to those of every block it shares an
  // interface with (K is 6 x 6 dense blocks on this pattern). Its lower triangle column by
  // column: (column, row) = (the smaller block, the larger).
  std::vector<std::pair<std::int64_t, std::int64_t>> pairs;
  for (const Interface& f : model.interfaces) {
    if (!f.is_support())
      pairs.emplace_back(std::min(f.block_i, f.block_j), std::max(f.block_i, f.block_j));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  // CHOLMOD's symbolic analysis of that graph, with its default ordering (the run orders the
  // same graph so: solve/sparse_cholesky.cpp), counts the non-zeros of its factor (lnz).
  double graph_factor = static_cast<double>(nb);
  if (nb > 1) {
    std::vector<std::int64_t> start(static_cast<std::size_t>(nb) + 1, 0);
    std::vector<std::int64_t> rows;
    rows.reserve(pairs.size() + static_cast<std::size_t>(nb));
    std::size_t k = 0;
    for (std::int64_t c = 0; c < nb; ++c) {
      start[static_cast<std::size_t>(c)] = static_cast<std::int64_t>(rows.size());
      rows.push_back(c);  // the diagonal first
      for (; k < pairs.size() && pairs[k].first == c; ++k)
        rows.push_back(pairs[k].second);
    }
    start[static_cast<std::size_t>(nb)] = static_cast<std::int64_t>(rows.size());
    cholmod_common cm;
    cholmod_l_start(&cm);
    cm.print = 0;
    cholmod_sparse a{};
    a.nrow = a.ncol = static_cast<std::size_t>(nb);
    a.nzmax = rows.size();
    a.p = start.data();
    a.i = rows.data();
    a.stype = -1;  // the lower triangle of a symmetric matrix
    a.itype = CHOLMOD_LONG;
    a.xtype = CHOLMOD_PATTERN;
    a.dtype = CHOLMOD_DOUBLE;
    a.sorted = 1;
    a.packed = 1;
    cholmod_factor* f = cholmod_l_analyze(&a, &cm);
    if (f) {
      graph_factor = cm.lnz;
      cholmod_l_free_factor(&f, &cm);
    }
    cholmod_l_finish(&cm);
  }
  // Each block entry of K or L is 36 numbers, a diagonal one 21 (its lower triangle).
  const auto pairs_count = static_cast<std::int64_t>(pairs.size());
  e.stiffness_nonzeros = 21 * nb + 36 * pairs_count;
  e.factor_nonzeros = 21 * nb + 36 * (static_cast<std::int64_t>(graph_factor) - nb);
  // Fitted to the peak resident sets of elastic runs of the rock slope example subdivided into
  // 3 195, 12 907 and 35 948 blocks (53, 191 and 585 MiB; docs/performance.md): 40 bytes per
  // non-zero of K (its values and 64-bit indices, about 2.5 copies: K, the copy in the
  // factor's order, the assembly's) and 10.5 per non-zero of L (the supernodes' padding, 1.2
  // times the count, and the factorization's workspace), and 8 MiB for the writers (cairo and
  // its fonts, the VTK file's buffers) that a check does not load.
  constexpr double kMiB = 1048576.0;
  e.solve_bytes = 40.0 * static_cast<double>(e.stiffness_nonzeros) +
                  10.5 * static_cast<double>(e.factor_nonzeros);
  e.peak_bytes = std::max(e.now_bytes, 0.0) + 8.0 * kMiB + e.solve_bytes;
  // A nonlinear run condenses K onto its plastic zone while the zone is at most
  // ZoneTuning::condensed_zone_fraction of the model; S on a zone that large, taken as dense (its
  // lower triangle, 8 bytes a number), bounds what that adds. Against measured peaks (the rock
  // slope example with strength and a surcharge: 430, 3 195 and 12 907 blocks, 24.8, 287 and 5 093
  // MiB) it is 16-40% over.
  if (!model.stages.empty()) {
    const double zone = 6.0 * ZoneTuning{}.condensed_zone_fraction * static_cast<double>(nb);
    e.nonlinear_bytes = e.peak_bytes + 4.0 * zone * zone;
  }
  return e;
}

}  // namespace bimrock
