// Block generation: cutting a 100 m x 100 m square by three fully persistent joint
// sets. The argument N = (100 m / spacing)^2, the number of spacing-sized squares in the domain:
// N = 100 (10 m, the CI smoke size), 2500 (2 m), 10000 (1 m), 40000 (0.5 m). Three sets in
// general position give about sum |sin(dip_i - dip_j)| * N crossings inside, hence about as
// many blocks. Run `make bench`; report medians of the repetitions. peak_rss_MiB is the
// process's resident-set high-water mark during the cuts.
#include <benchmark/benchmark.h>

#include <cmath>

#include <bimrock/analysis/memory_probe.hpp>
#include <bimrock/geometry/block_cutter.hpp>

namespace bimrock {
namespace {

std::vector<JointTrace> three_sets(const Domain& d, double spacing) {
  // Dips and origins chosen so that no three joints meet at a point (a triangular lattice
  // would make every crossing a near-triple point, i.e. a sliver).
  const std::vector<JointSet> sets{
      {.material = "a", .dip_deg = 15.0, .spacing = spacing, .origin = Vec2(0.13, 0.29) * spacing},
      {.material = "b", .dip_deg = 75.0, .spacing = spacing, .origin = Vec2(0.41, 0.07) * spacing},
      {.material = "c",
       .dip_deg = 140.0,
       .spacing = spacing,
       .origin = Vec2(0.23, 0.37) * spacing}};
  return generate_traces(sets, {}, bbox_of(d));
}

void BM_CutBlocks(benchmark::State& state) {
  const Domain d{{{{0, 0}, {100, 0}, {100, 100}, {0, 100}}}, {}, {}};
  const double spacing = 100.0 / std::sqrt(static_cast<double>(state.range(0)));
  const std::vector<JointTrace> traces = three_sets(d, spacing);
  const CutOptions options{.min_block_area = 0.01 * spacing * spacing};
  std::size_t n_blocks = 0;
  std::size_t n_vertices = 0;
  // The process's peak resident set during the cuts (freed heap of earlier runs is reused, so
  // every run sees about the same peak).
  reset_peak_memory();
  for (auto _ : state) {
    const BlockCut cut = cut_blocks(d, traces, options);
    n_blocks = cut.blocks.size();
    n_vertices = cut.vertices.size();
    benchmark::DoNotOptimize(cut.blocks.data());
  }
  state.counters["peak_rss_MiB"] = static_cast<double>(peak_memory_bytes()) / (1024.0 * 1024.0);
  state.counters["spacing_m"] = spacing;
  state.counters["traces"] = static_cast<double>(traces.size());
  state.counters["blocks"] = static_cast<double>(n_blocks);
  state.counters["vertices"] = static_cast<double>(n_vertices);
  state.counters["blocks_per_s"] = benchmark::Counter(
      static_cast<double>(n_blocks), benchmark::Counter::kIsIterationInvariantRate);
}

BENCHMARK(BM_CutBlocks)->Arg(100)->Arg(2500)->Arg(10000)->Arg(40000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace bimrock
