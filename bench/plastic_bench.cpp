// Benchmark of the nonlinear analysis: the brick mass of brick_mass.hpp with plastic
// joints (Mohr-Coulomb, friction 35 deg, cohesion 0.1 MPa) loaded by gravity in 5 increments,
// with a tensile strength of 10 kPa (BM_PlasticGravity) or none (BM_PlasticGravityNoTension:
// the vertical joints of a free-standing wall carry no normal stress, so nearly all of them sit
// on the tension cut-off and open: the LCP holds most of the joints, the hard case). Counters: the
// LCP rows and Lemke pivots per increment (largest and mean), yielding and open points at the end,
// and seconds per increment.
#include <algorithm>

#include <benchmark/benchmark.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "brick_mass.hpp"

namespace bimrock {
namespace {

void run_plastic_gravity(benchmark::State& state, double tensile) {
  const Model m =
      build_model(bench::plastic_brick_mass_case(static_cast<int>(state.range(0)), tensile, 5));
  PlasticResult r;
  for (auto _ : state)
    r = run_plastic_analysis(m);
  state.counters["blocks"] = m.n_blocks();
  state.counters["yield_points"] = static_cast<double>(r.points.size());
  double lcp_max = 0, lcp_sum = 0, pivots = 0, newton = 0, seconds = 0;
  for (const IncrementRecord& h : r.history) {
    lcp_max = std::max(lcp_max, static_cast<double>(h.lcp_size));
    lcp_sum += h.lcp_size;
    pivots += h.pivots;
    newton += h.active_set_iterations;
    seconds += h.seconds;
  }
  const double n = std::max<double>(1.0, static_cast<double>(r.history.size()));
  state.counters["increments"] = static_cast<double>(r.history.size());
  state.counters["lcp_rows_max"] = lcp_max;
  state.counters["lcp_rows_mean"] = lcp_sum / n;
  state.counters["pivots_per_increment"] = pivots / n;
  state.counters["active_set_iterations_per_increment"] = newton / n;
  state.counters["s_per_increment"] = seconds / n;
  state.counters["yielding_last"] = r.history.empty() ? 0 : r.history.back().yielding_points;
  state.counters["open_last"] = r.history.empty() ? 0 : r.history.back().open_points;
  state.counters["collapsed"] = r.collapse ? 1 : 0;
}

void BM_PlasticGravity(benchmark::State& state) {
  run_plastic_gravity(state, 10e3);
}
void BM_PlasticGravityNoTension(benchmark::State& state) {
  run_plastic_gravity(state, 0.0);
}

BENCHMARK(BM_PlasticGravity)->RangeMultiplier(10)->Range(100, 10000)->Unit(benchmark::kMillisecond);
// Dense Lemke on ~3 rows per block: 10^3 blocks take ~10 s per increment; larger sizes wait for
// the sparse LCP routes.
BENCHMARK(BM_PlasticGravityNoTension)
    ->RangeMultiplier(10)
    ->Range(100, 1000)
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace bimrock
