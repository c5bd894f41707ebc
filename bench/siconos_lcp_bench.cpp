// Our LCP solvers against a peer, Siconos Numerics, on the dense LCPs of single
// increments of our own models (model_lcps.hpp): (a) the brick mass with no-tension joints at
// its first gravity increment, (b) the jointed wall at its last increment before collapse, (c)
// the same wall at an increment that ends exactly at its limit load. The argument is the model's
// block count. Compiled only when Siconos is found (CMakeLists.txt).
//
// Each benchmark solves one LCP with one solver: our primal-dual active-set method, our Lemke,
// Siconos' Lemke, or Siconos' Newton-min/FB (given the LCP equilibrated by powers of two, see
// SiconosLcp for why, and like our active-set method the analysis' warm start). Nothing is
// asserted about time. After solving, the
// solution is compared with ours (the active set's, or our Lemke's where it fails) and reported
// as counters: rows, solved (the solver's own claim), steps (pivots or iterations), residual
// (LcpResiduals::worst_relative), complementarity (relative) and complementarity_abs (max
// |z_i w_i|), diff_rel = |z - z_ours|_inf / |z_ours|_inf and diff_scaled =
// |z - z_ours|_inf / max(1, |z_ours|_inf). A solver that claims success but differs from ours by
// more than 1e-9 relative fails the run. bimrock_lcp_table prints the same comparison as a table.
#include <exception>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/lemke.hpp>

#include "model_lcps.hpp"
#include "siconos_lcp.hpp"

namespace bimrock::bench {
namespace {

enum class Source { brick_mass, wall_near_collapse, wall_at_limit };
enum class Method { active_set, lemke, siconos_lemke, siconos_newton_min_fb };

// The analysis' warm start of the LCP, if any (the active-set method and Siconos' Newton use it).
const Eigen::VectorXd* warm_start(const ModelLcp& lcp) {
  return lcp.warm_start.size() > 0 ? &lcp.warm_start : nullptr;
}

// An LCP of a model and our solution of it (the analysis' route: the active-set method, Lemke
// where it fails), built once per size for every benchmark.
struct Reference {
  ModelLcp lcp;
  LcpResult ours;
};

const Reference& reference(Source source, int blocks) {
  static std::map<std::pair<Source, int>, std::unique_ptr<Reference>> cache;
  std::unique_ptr<Reference>& entry = cache[{source, blocks}];
  if (!entry) {
    entry = std::make_unique<Reference>();
    switch (source) {
      case Source::brick_mass:
        entry->lcp = brick_mass_gravity_lcp(blocks);
        break;
      case Source::wall_near_collapse:
        entry->lcp = wall_near_collapse_lcp(blocks);
        break;
      case Source::wall_at_limit:
        entry->lcp = wall_at_limit_lcp(blocks);
        break;
    }
    entry->ours = ActiveSetLcp().solve(entry->lcp.problem, warm_start(entry->lcp));
    if (entry->ours.status != LcpStatus::solved)
      entry->ours = Lemke().solve(entry->lcp.problem);
  }
  return *entry;
}

std::unique_ptr<LcpSolver> make_solver(Method method) {
  switch (method) {
    case Method::active_set:
      return std::make_unique<ActiveSetLcp>();
    case Method::lemke:
      return std::make_unique<Lemke>();
    case Method::siconos_lemke:
      return std::make_unique<SiconosLcp>(SiconosMethod::lemke);
    case Method::siconos_newton_min_fb:
      return std::make_unique<SiconosLcp>(SiconosMethod::newton_min_fb);
  }
  return nullptr;
}

void solve_model_lcp(benchmark::State& state, Source source, Method method) {
  const Reference* found = nullptr;
  try {
    found = &reference(source, static_cast<int>(state.range(0)));
  } catch (const std::exception& e) {
    state.SkipWithError(e.what());  // the model did not reach the state of its LCP
    return;
  }
  const Reference& ref = *found;
  const std::unique_ptr<LcpSolver> solver = make_solver(method);
  LcpResult r;
  for (auto _ : state) {
    r = solver->solve(ref.lcp.problem, warm_start(ref.lcp));
    benchmark::DoNotOptimize(r.z.data());
  }
  state.counters["blocks"] = ref.lcp.blocks;
  state.counters["rows"] = static_cast<double>(ref.lcp.problem.size());
  state.counters["analysis_rows"] = ref.lcp.analysis_rows;
  state.counters["analysis_pivots"] = ref.lcp.analysis_pivots;
  state.counters["solved"] = r.status == LcpStatus::solved ? 1 : 0;
  state.counters["steps"] = r.steps;
  state.counters["residual"] = r.residuals.worst_relative();
  state.counters["complementarity"] = r.residuals.complementarity;
  state.counters["complementarity_abs"] = r.residuals.max_complementarity;
  if (const auto* peer = dynamic_cast<const SiconosLcp*>(solver.get())) {
    state.counters["siconos_info"] = peer->last_info();
    state.counters["siconos_error"] = peer->last_error();
  }
  if (ref.ours.status != LcpStatus::solved) {
    state.counters["ours_solved"] = 0;
    return;  // nothing to compare with: reported, not failed (the table says why)
  }
  const SolutionDifference d = compare_solutions(r.z, ref.ours.z);
  state.counters["diff_rel"] = d.relative;
  state.counters["diff_scaled"] = d.scaled;
  if (r.status == LcpStatus::solved && d.relative > kAgreement)
    state.SkipWithError((solver->name() + " claims a solution that differs from ours by " +
                         std::to_string(d.relative) + " (relative)")
                            .c_str());
}

// Block counts giving LCPs of about 300, 1000, 2000 and 3000 rows for the brick mass, 700 to 2000
// for the walls (3000 rows would take a wall of ~1000 blocks and minutes of analysis to reach
// the state). The smallest of each is the CI smoke size (bench_smoke runs names ending in /100).
void register_all() {
  const std::pair<Method, const char*> methods[] = {
      {Method::active_set, "ActiveSet"},
      {Method::lemke, "Lemke"},
      {Method::siconos_lemke, "SiconosLemke"},
      {Method::siconos_newton_min_fb, "SiconosNewtonMinFb"}};
  const std::pair<Source, const char*> sources[] = {
      {Source::brick_mass, "BM_LcpBrickMass"},
      {Source::wall_near_collapse, "BM_LcpWallNearCollapse"},
      {Source::wall_at_limit, "BM_LcpWallAtLimit"}};
  for (const auto& [source, source_name] : sources) {
    for (const auto& [method, method_name] : methods) {
      const std::string name = std::string(source_name) + "/" + method_name;
      auto* b = benchmark::RegisterBenchmark(name.c_str(), solve_model_lcp, source, method);
      if (source == Source::brick_mass)
        b->Arg(100)->Arg(400)->Arg(700)->Arg(1000);
      else
        b->Arg(100)->Arg(160)->Arg(290)->Arg(460);
      // The "Time" column is wall-clock time (UseRealTime() would append "/real_time" to the
      // names).
      b->Unit(benchmark::kMillisecond);
    }
  }
}

const bool registered = (register_all(), true);

}  // namespace
}  // namespace bimrock::bench
