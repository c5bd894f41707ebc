// Kernel benchmarks of the static condensation of K onto a plastic zone: K factorized
// with the zone's blocks ordered last (against BM_Factorize, K in its own best order), the
// zone's Schur complement read from that factor, and a factorization of the Schur complement
// (what each active-set iteration of a condensed analysis pays instead of a whole tangent's),
// and solves with the Schur complement through K's factor (SchurSolver) against a factor of its
// own.
// The zone: the blocks nearest the mass's centre, an eighth of them (at 10^4 blocks the plastic
// zone of `bimrock bench`'s plastic model at collapse holds 12% of its blocks).
#include <algorithm>
#include <numeric>

#include <benchmark/benchmark.h>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/solve/schur_solver.hpp>
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

// The brick mass of state.range(0) blocks, its K and the central zone; `factorized`: K also
// analyzed with the zone last and factorized.
struct ZoneCase {
  ZoneCase(const benchmark::State& state, bool factorized)
      : model(build_model(bench::brick_mass_case(static_cast<int>(state.range(0))))),
        lower(assemble_stiffness_lower(model)),
        zone(central_zone(model, 0.125)) {
    if (factorized) {
      k.analyze_last(lower, 6, zone);
      k.factorize(lower);
    }
  }
  void set_counters(benchmark::State& state) const {
    state.counters["blocks"] = model.n_blocks();
    state.counters["zone_unknowns"] = static_cast<double>(k.trailing_unknowns().size());
    state.counters["factor_nnz"] = static_cast<double>(k.factor_nonzeros());
  }
  Model model;
  SparseMatrix lower;
  std::vector<char> zone;
  SparseCholesky k;
};

void BM_AnalyzeZoneLast(benchmark::State& state) {
  ZoneCase c(state, false);
  for (auto _ : state)
    c.k.analyze_last(c.lower, 6, c.zone);
  c.set_counters(state);
}

void BM_FactorizeZoneLast(benchmark::State& state) {
  ZoneCase c(state, true);
  for (auto _ : state)
    benchmark::DoNotOptimize(c.k.factorize(c.lower));
  c.set_counters(state);
}

void BM_SchurComplement(benchmark::State& state) {
  ZoneCase c(state, true);
  for (auto _ : state)
    benchmark::DoNotOptimize(c.k.schur_complement(c.lower));
  c.set_counters(state);
  state.counters["schur_nnz"] = static_cast<double>(c.k.schur_complement(c.lower).nonZeros());
}

void BM_FactorizeSchur(benchmark::State& state) {
  ZoneCase c(state, true);
  const SparseMatrix s = c.k.schur_complement(c.lower);
  SparseCholesky chol;
  chol.analyze(s, 6);
  for (auto _ : state)
    benchmark::DoNotOptimize(chol.factorize(s));
  c.set_counters(state);
  state.counters["schur_factor_nnz"] = static_cast<double>(chol.factor_nonzeros());
}

// `columns` right-hand sides solved with S (1: one vector), through `solver`.
void solve_with(benchmark::State& state, const SpdSolver& solver, Eigen::Index columns) {
  const Eigen::MatrixXd b = Eigen::MatrixXd::Ones(solver.rows(), columns);
  const Eigen::VectorXd v = Eigen::VectorXd::Ones(solver.rows());
  for (auto _ : state) {
    if (columns == 1)
      benchmark::DoNotOptimize(solver.solve(v));
    else
      benchmark::DoNotOptimize(solver.solve(b));
  }
  state.counters["solver_nnz"] = static_cast<double>(solver.factor_nonzeros());
}

// What the analysis does: forward and back through L_PP, K's factor's trailing
// block (L_PP L_PP^T = S).
void BM_SolveSchurTrailing(benchmark::State& state, Eigen::Index columns) {
  ZoneCase c(state, true);
  solve_with(state, SchurSolver(c.k, 1), columns);
  c.set_counters(state);
}

// What it did before: S factorized in its own order (CHOLMOD's supernodal solve).
void BM_SolveSchurOwnFactor(benchmark::State& state, Eigen::Index columns) {
  ZoneCase c(state, true);
  const SparseMatrix s = c.k.schur_complement(c.lower);
  SparseCholesky chol;
  chol.analyze(s, 6);
  chol.factorize(s);
  solve_with(state, chol, columns);
  c.set_counters(state);
}

#define BIMROCK_ZONE_SIZES RangeMultiplier(10)->Range(100, 100000)->Unit(benchmark::kMillisecond)
BENCHMARK(BM_AnalyzeZoneLast)->BIMROCK_ZONE_SIZES;
BENCHMARK(BM_FactorizeZoneLast)->BIMROCK_ZONE_SIZES;
BENCHMARK(BM_SchurComplement)->BIMROCK_ZONE_SIZES;
BENCHMARK(BM_FactorizeSchur)->BIMROCK_ZONE_SIZES;
BENCHMARK_CAPTURE(BM_SolveSchurTrailing, vector, 1)->BIMROCK_ZONE_SIZES;
BENCHMARK_CAPTURE(BM_SolveSchurTrailing, columns32, 32)->BIMROCK_ZONE_SIZES;
BENCHMARK_CAPTURE(BM_SolveSchurOwnFactor, vector, 1)->BIMROCK_ZONE_SIZES;
BENCHMARK_CAPTURE(BM_SolveSchurOwnFactor, columns32, 32)->BIMROCK_ZONE_SIZES;

}  // namespace
}  // namespace bimrock
