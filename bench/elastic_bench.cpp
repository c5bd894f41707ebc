// Kernel benchmarks of the elastic analysis of a brick mass:
// model building (interface detection), assembly of K, symbolic and numeric factorization, one
// solve, and the whole elastic analysis. Run `make bench`; report medians of the repetitions.
#include <benchmark/benchmark.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

#include "brick_mass.hpp"

namespace bimrock {
namespace {

void set_size_counters(benchmark::State& state, const Model& m) {
  state.counters["blocks"] = m.n_blocks();
  state.counters["interfaces"] = m.n_interfaces();
  state.counters["unknowns"] = m.n_dofs();
}

void BM_BuildModel(benchmark::State& state) {
  const CaseSpec c = bench::brick_mass_case(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(build_model(c));
  set_size_counters(state, build_model(c));
}

void BM_AssembleStiffness(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(assemble_stiffness_lower(m));
  set_size_counters(state, m);
}

void BM_AnalyzePattern(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix k = assemble_stiffness_lower(m);
  for (auto _ : state) {
    SparseCholesky chol;
    chol.analyze(k, 6);
    state.counters["factor_nnz"] = static_cast<double>(chol.factor_nonzeros());
  }
  set_size_counters(state, m);
}

void BM_Factorize(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix k = assemble_stiffness_lower(m);
  SparseCholesky chol;
  chol.analyze(k, 6);
  for (auto _ : state)
    benchmark::DoNotOptimize(chol.factorize(k));
  set_size_counters(state, m);
  state.counters["factor_nnz"] = static_cast<double>(chol.factor_nonzeros());
}

// One solve with K's factor for `columns` right-hand sides at once (the reduced tangent's
// low-rank updates solve their new columns so): the time per column falls with their number,
// since the factor is read once per solve.
void solve_columns(benchmark::State& state, Eigen::Index columns) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  const SparseMatrix k = assemble_stiffness_lower(m);
  const Eigen::MatrixXd b = assemble_loads(m, m.loads).replicate(1, columns);
  SparseCholesky chol;
  chol.analyze(k, 6);
  chol.factorize(k);
  for (auto _ : state)
    benchmark::DoNotOptimize(chol.solve(b));
  set_size_counters(state, m);
  state.counters["columns"] = static_cast<double>(columns);
}

void BM_Solve(benchmark::State& state) {
  solve_columns(state, 1);
}
void BM_SolveColumns(benchmark::State& state) {
  solve_columns(state, state.range(1));
}

// The whole elastic analysis from a model: check supports, assemble, analyze, factorize, solve,
// evaluate every block and interface (no results written).
void BM_ElasticAnalysis(benchmark::State& state) {
  const Model m = build_model(bench::brick_mass_case(static_cast<int>(state.range(0))));
  for (auto _ : state)
    benchmark::DoNotOptimize(solve_elastic(m));
  set_size_counters(state, m);
}

#define BIMROCK_SIZES RangeMultiplier(10)->Range(100, 100000)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_BuildModel)->BIMROCK_SIZES;
BENCHMARK(BM_AssembleStiffness)->BIMROCK_SIZES;
BENCHMARK(BM_AnalyzePattern)->BIMROCK_SIZES;
// 10^6 blocks: the symbolic analysis alone, which gives the factor's size (docs/performance.md:
// 17 GB of values; the whole 10^6-block elastic run fits this 24 GiB machine with < 1 GiB spare).
BENCHMARK(BM_AnalyzePattern)->Arg(1000000)->Iterations(1)->Unit(benchmark::kSecond);
BENCHMARK(BM_Factorize)->BIMROCK_SIZES;
BENCHMARK(BM_Solve)->BIMROCK_SIZES;
BENCHMARK(BM_SolveColumns)
    ->ArgsProduct({{1000, 10000}, {1, 8, 32, 128}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ElasticAnalysis)->BIMROCK_SIZES;

}  // namespace
}  // namespace bimrock
