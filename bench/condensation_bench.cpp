// Kernel benchmarks of the static condensation of K onto a plastic zone (issue 5): K factorized
// with the zone's blocks ordered last (against BM_Factorize, K in its own best order), the
// zone's Schur complement read from that factor, and a factorization of the Schur complement
// (what each active-set iteration of a condensed analysis pays instead of a whole tangent's).
// The zone: the blocks nearest the mass's centre, an eighth of them (at 10^4 blocks the plastic
// zone of `bimrock bench`'s plastic model at collapse holds 12% of its blocks).
#include <algorithm>
#include <numeric>

#include <benchmark/benchmark.h>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

#include "brick_mass.hpp"

namespace bimrock {
namespace {

std::vector<char> central_zone(const Model& m, double fraction) {
  Vec2 centre = Vec2::Zero();
  for (const Block& b : m.blocks)
    centre += b.centroid / m.n_blocks();
  std::vector<int> order(static_cast<std::size_t>(m.n_blocks()));
  std::iota(order.begin(), order.end(), 0);
  const auto distance = [&](int b) { return (m.blocks[b].centroid - centre).norm(); };
  const auto count = static_cast<std::ptrdiff_t>(fraction * m.n_blocks());
  std::nth_element(order.begin(), order.begin() + count, order.end(),
                   [&](int a, int b) { return distance(a) < distance(b); });
  std::vector<char> zone(order.size(), 0);
  for (std::ptrdiff_t k = 0; k < count; ++k)
    zone[static_cast<std::size_t>(order[k])] = 1;
  return zone;
}

void set_counters(benchmark::State& state, const Model& m, const SparseCholesky& k) {
  state.counters["blocks"] = m.n_blocks();
  state.counters["zone_unknowns"] = static_cast<double>(k.trailing_unknowns().size());
  state.counters["factor_nnz"] = static_cast<double>(k.factor_nonzeros());
}

void BM_AnalyzeZoneLast(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix lower = assemble_stiffness_lower(m);
  const std::vector<char> zone = central_zone(m, 0.125);
  SparseCholesky k;
  for (auto _ : state)
    k.analyze_last(lower, 6, zone);
  set_counters(state, m, k);
}

void BM_FactorizeZoneLast(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix lower = assemble_stiffness_lower(m);
  SparseCholesky k;
  k.analyze_last(lower, 6, central_zone(m, 0.125));
  for (auto _ : state)
    benchmark::DoNotOptimize(k.factorize(lower));
  set_counters(state, m, k);
}

void BM_SchurComplement(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix lower = assemble_stiffness_lower(m);
  SparseCholesky k;
  k.analyze_last(lower, 6, central_zone(m, 0.125));
  k.factorize(lower);
  for (auto _ : state)
    benchmark::DoNotOptimize(k.schur_complement(lower));
  set_counters(state, m, k);
  state.counters["schur_nnz"] = static_cast<double>(k.schur_complement(lower).nonZeros());
}

void BM_FactorizeSchur(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix lower = assemble_stiffness_lower(m);
  SparseCholesky k;
  k.analyze_last(lower, 6, central_zone(m, 0.125));
  k.factorize(lower);
  const SparseMatrix s = k.schur_complement(lower);
  SparseCholesky chol;
  chol.analyze(s, 6);
  for (auto _ : state)
    benchmark::DoNotOptimize(chol.factorize(s));
  set_counters(state, m, k);
  state.counters["schur_factor_nnz"] = static_cast<double>(chol.factor_nonzeros());
}

BENCHMARK(BM_AnalyzeZoneLast)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FactorizeZoneLast)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SchurComplement)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FactorizeSchur)
    ->RangeMultiplier(10)
    ->Range(1000, 100000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace bimrock
