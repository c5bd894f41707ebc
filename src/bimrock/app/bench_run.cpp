#include "bimrock/app/bench_run.hpp"

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <optional>
#include <stdexcept>

#include <fmt/core.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/memory_probe.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/io/results_writer.hpp>
#include <bimrock/solve/factor_memory.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock::bench {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

void add(Run& run, const std::string& phase, double s, double peak = -1) {
  run.seconds.emplace_back(phase, s);
  if (peak >= 0)
    run.peak_bytes[phase] = peak;
}

void add_timings(Run& run, const Timings& t) {
  for (const auto& [phase, s] : t.phases) {
    const auto peak = t.peak_bytes.find(phase);
    add(run, phase, s, peak == t.peak_bytes.end() ? -1.0 : static_cast<double>(peak->second));
  }
}

// The physical limit: CHOLMOD alone on the model's K (assembled outside the clock).
// Its memory counts K too: the peak over the resident set before K was assembled.
void measure_limit(const Model& model, Run& run) {
  // CHOLMOD alone, as it is with glibc's allocator: without the analyses' recycling of its large
  // blocks (factor_memory.hpp), whose kept pages would count in its peak.
  const struct GlibcAllocator {
    GlibcAllocator() { recycle_factor_memory(false); }
    ~GlibcAllocator() { recycle_factor_memory(true); }
  } glibc_allocator;
  release_free_memory();
  const double before = static_cast<double>(current_memory_bytes());
  reset_peak_memory();
  const SparseMatrix k = assemble_stiffness_lower(model);
  const Eigen::VectorXd p = Eigen::VectorXd::Ones(model.n_dofs());
  const auto start = Clock::now();
  SparseCholesky cholesky;
  cholesky.analyze(k, 6);
  if (!cholesky.factorize(k))
    throw std::runtime_error("bench: K is not positive definite");
  const Eigen::VectorXd u = cholesky.solve(p);
  run.limit_seconds = seconds_since(start);
  run.limit_peak_bytes = static_cast<double>(peak_memory_bytes()) - before;
  if (!u.allFinite())
    throw std::runtime_error("bench: the solve failed");
}

// The plastic zone: the blocks of every point that has yielded or opened so far, and how many
// of them border a block outside it (what a static condensation onto the zone would leave
// dense).
std::pair<int, int> plastic_zone(const Model& model, const std::vector<YieldPoint>& points,
                                 const AnalysisState& st) {
  std::vector<char> in(static_cast<std::size_t>(model.n_blocks()), 0);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const PlasticState& s = st.points[p];
    if (s.slip == 0.0 && s.gap == 0.0 && s.plastic.isZero(0.0))
      continue;
    flag_blocks(points[p], in);
  }
  std::vector<char> boundary(in.size(), 0);
  for (const Interface& f : model.interfaces) {
    if (f.is_support())
      continue;
    const auto i = static_cast<std::size_t>(f.block_i), j = static_cast<std::size_t>(f.block_j);
    if (in[i] != in[j])
      boundary[in[i] ? i : j] = 1;
  }
  return {static_cast<int>(std::count(in.begin(), in.end(), 1)),
          static_cast<int>(std::count(boundary.begin(), boundary.end(), 1))};
}

}  // namespace

Run run_elastic(int n, const fs::path& scratch, const ElasticSolve& solve,
                const RunSettings& settings) {
  Run run;
  CaseSpec spec = brick_mass_case(n);
  std::vector<Polygon> polygons;
  for (const BlockSpec& b : spec.blocks)
    polygons.push_back(b.polygon);
  release_free_memory();
  const double before = static_cast<double>(current_memory_bytes());
  reset_peak_memory();
  auto start = Clock::now();
  const Model model = build_model(spec);
  add(run, "build model", seconds_since(start), static_cast<double>(peak_memory_bytes()));
  std::vector<BlockSpec>().swap(spec.blocks);  // as `bimrock run` does once the model is built
  {
    // Interface detection alone, timed again (build_model did it); its result and the
    // polygons are not kept beside the analysis.
    start = Clock::now();
    const std::vector<SharedEdge> edges = find_shared_edges(polygons, model.tolerance);
    add(run, "(of which interface detection)", seconds_since(start));
    std::vector<Polygon>().swap(polygons);
  }
  const ElasticSolution s = solve(model, run);
  run.run_peak_bytes = static_cast<double>(peak_memory_bytes()) - before;
  add_timings(run, s.timings);
  run.blocks = model.n_blocks();
  run.unknowns = model.n_dofs();
  run.interfaces = model.n_interfaces();
  if (!settings.first_process)
    return run;
  start = Clock::now();
  write_elastic_results(model, s, {}, scratch / "elastic");
  add(run, "write results", seconds_since(start));
  if (settings.limit)
    measure_limit(model, run);
  return run;
}

Run run_plastic(int n, int increments, JointFlow flow, bool factor_of_safety,
                const fs::path& scratch, const RunSettings& settings) {
  Run run;
  release_free_memory();
  const double before = static_cast<double>(current_memory_bytes());
  reset_peak_memory();
  auto start = Clock::now();
  // Pushed to 1.2 times the closed-form collapse thrust: collapses within the stage; for the
  // factor of safety, to 0.6 times it: carried, then the strengths reduced to collapse.
  const double thrust = (factor_of_safety ? 0.6 : 1.2) * abutment_collapse_shear();
  const Model model = build_model(abutment_case(n, increments, thrust, flow));
  PlasticOptions options;
  if (factor_of_safety)
    options.factor_of_safety = FactorOfSafetyOptions{};
  PlasticTuning tuning;
  if (settings.stiffness)
    tuning.stiffness = settings.stiffness(model);
  add(run, "build model", seconds_since(start), static_cast<double>(peak_memory_bytes()));
  double writing = 0.0;
  PlasticResult result;
  std::vector<YieldPoint> points;  // for the verbose lines only
  {
    // Written by the first process only, as `bimrock run` does.
    std::optional<PlasticResultsWriter> writer;
    if (settings.first_process)
      writer.emplace(model, OutputOptions{}, scratch / "plastic");
    const auto on_increment = [&](const IncrementRecord& r, const AnalysisState& st) {
      const auto w = Clock::now();
      if (writer)
        writer->on_increment(r, st);
      if (std::getenv("BIMROCK_BENCH_VERBOSE")) {
        if (points.empty())
          points = make_yield_points(model);
        const auto [zone, boundary] = plastic_zone(model, points, st);
        fmt::print(stderr,
                   "  stage {} inc {} factor {:.4f} lcp {} yielding {} open {} as-it {} "
                   "tangent {} pivots {} rounds {} {:.3f} s, growth now {:.0f} MiB, peak "
                   "{:.0f} MiB, plastic zone {} blocks ({} on its boundary)\n",
                   r.stage, r.increment, r.stage_factor, r.lcp_size, r.yielding_points,
                   r.open_points, r.active_set_iterations, r.tangent_factorizations, r.pivots,
                   r.rounds, r.seconds,
                   (static_cast<double>(current_memory_bytes()) - before) / 1048576.0,
                   (static_cast<double>(peak_memory_bytes()) - before) / 1048576.0, zone, boundary);
      }
      writing += seconds_since(w);
    };
    result = run_plastic_analysis(model, options, on_increment, tuning);
    if (std::getenv("BIMROCK_BENCH_VERBOSE")) {
      if (result.collapse)
        fmt::print(stderr, "  collapse in stage {} between factors {:.6f} and {:.6f}\n",
                   result.collapse->stage, result.collapse->carried, result.collapse->failed);
      if (result.stopped)
        fmt::print(stderr, "  stopped in stage {} at factor {:.6f}: {}\n", result.stopped->stage,
                   result.stopped->factor, result.stopped->reason);
    }
    run.run_peak_bytes = static_cast<double>(peak_memory_bytes()) - before;
    if (settings.sum_over_processes) {
      run.method = settings.stiffness_method;
      run.processes = settings.processes;
      run.all_processes_peak_bytes =
          settings.sum_over_processes(static_cast<double>(peak_memory_bytes()));
    }
    start = Clock::now();
    if (writer)
      (void)writer->finish(result);
    writing += seconds_since(start);
  }
  add_timings(run, result.timings);
  add(run, "write results", writing);
  run.blocks = model.n_blocks();
  run.unknowns = model.n_dofs();
  run.interfaces = model.n_interfaces();
  run.yield_points = static_cast<int>(result.points.size());
  run.increments = static_cast<int>(result.history.size());
  for (const IncrementRecord& h : result.history)
    run.lcp_rows_max = std::max(run.lcp_rows_max, h.lcp_size);
  run.collapsed = result.collapse.has_value() ||
                  (result.factor_of_safety && result.factor_of_safety->collapse.has_value());
  run.condensations = result.condensations;
  run.reserve_switches = result.reserve_switches;
  run.regions = result.regions;
  run.zone_blocks = result.zone_blocks;
  if (settings.limit && settings.first_process)
    measure_limit(model, run);
  return run;
}

}  // namespace bimrock::bench
