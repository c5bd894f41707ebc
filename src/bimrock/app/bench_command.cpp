#include "bimrock/app/bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <thread>

#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/memory_probe.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/io/line_plot.hpp>
#include <bimrock/io/results_writer.hpp>
#include <bimrock/model/reference_cases.hpp>
#include <bimrock/solve/factor_memory.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// One run of one model: seconds and peak bytes per phase, in order, plus sizes.
struct Run {
  std::vector<std::pair<std::string, double>> seconds;
  std::map<std::string, double> peak_bytes;
  double limit_seconds = 0.0;  ///< analyze + factorize + one solve of the same K, alone
  double limit_peak_bytes = 0.0;
  double run_peak_bytes = 0.0;  ///< whole analysis, results not written
  int blocks = 0, interfaces = 0, unknowns = 0, yield_points = 0, lcp_rows_max = 0, increments = 0;
  bool collapsed = false;
  int condensations = 0;     ///< times K was condensed onto a plastic zone
  int reserve_switches = 0;  ///< times a zone was replaced by a reserve of the same factor
  int regions = 0;           ///< times K was factorized onto a region (zones then come from it)
  int zone_blocks = 0;       ///< blocks of the last zone
};

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

Run run_elastic(int n, const fs::path& scratch) {
  Run run;
  const CaseSpec spec = brick_mass_case(n);
  std::vector<Polygon> polygons;
  for (const BlockSpec& b : spec.blocks)
    polygons.push_back(b.polygon);
  release_free_memory();
  const double before = static_cast<double>(current_memory_bytes());
  reset_peak_memory();
  auto start = Clock::now();
  const Model model = build_model(spec);
  add(run, "build model", seconds_since(start), static_cast<double>(peak_memory_bytes()));
  start = Clock::now();
  const std::vector<SharedEdge> edges = find_shared_edges(polygons, model.tolerance);
  add(run, "(of which interface detection)", seconds_since(start));
  const ElasticSolution s = solve_elastic(model);
  run.run_peak_bytes = static_cast<double>(peak_memory_bytes()) - before;
  add_timings(run, s.timings);
  start = Clock::now();
  write_elastic_results(model, s, {}, scratch / "elastic");
  add(run, "write results", seconds_since(start));
  run.blocks = model.n_blocks();
  run.unknowns = model.n_dofs();
  run.interfaces = model.n_interfaces();
  measure_limit(model, run);
  return run;
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

Run run_plastic(int n, int increments, JointFlow flow, const fs::path& scratch) {
  Run run;
  release_free_memory();
  const double before = static_cast<double>(current_memory_bytes());
  reset_peak_memory();
  auto start = Clock::now();
  // Pushed to 1.2 times the closed-form collapse thrust: collapses within the stage.
  const Model model =
      build_model(abutment_case(n, increments, 1.2 * abutment_collapse_shear(), flow));
  add(run, "build model", seconds_since(start), static_cast<double>(peak_memory_bytes()));
  double writing = 0.0;
  PlasticResult result;
  std::vector<YieldPoint> points;  // for the verbose lines only
  {
    PlasticResultsWriter writer(model, {}, scratch / "plastic");
    result =
        run_plastic_analysis(model, {}, [&](const IncrementRecord& r, const AnalysisState& st) {
          const auto w = Clock::now();
          writer.on_increment(r, st);
          if (std::getenv("BIMROCK_BENCH_VERBOSE")) {
            if (points.empty())
              points = make_yield_points(model);
            const auto [zone, boundary] = plastic_zone(model, points, st);
            fmt::print(
                stderr,
                "  stage {} inc {} factor {:.4f} lcp {} yielding {} open {} as-it {} "
                "tangent {} pivots {} rounds {} {:.3f} s, growth now {:.0f} MiB, peak "
                "{:.0f} MiB, plastic zone {} blocks ({} on its boundary)\n",
                r.stage, r.increment, r.stage_factor, r.lcp_size, r.yielding_points, r.open_points,
                r.active_set_iterations, r.tangent_factorizations, r.pivots, r.rounds, r.seconds,
                (static_cast<double>(current_memory_bytes()) - before) / 1048576.0,
                (static_cast<double>(peak_memory_bytes()) - before) / 1048576.0, zone, boundary);
          }
          writing += seconds_since(w);
        });
    run.run_peak_bytes = static_cast<double>(peak_memory_bytes()) - before;
    start = Clock::now();
    (void)writer.finish(result);
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
  run.collapsed = result.collapse.has_value();
  run.condensations = result.condensations;
  run.reserve_switches = result.reserve_switches;
  run.regions = result.regions;
  run.zone_blocks = result.zone_blocks;
  measure_limit(model, run);
  return run;
}

double total_without_writing(const Run& r) {
  double t = 0.0;
  for (const auto& [phase, s] : r.seconds)
    if (phase != "write results" && phase.front() != '(')
      t += s;
  return t;
}

struct Row {
  std::string model;
  Run first;  // sizes and counts
  std::vector<std::pair<std::string, double>> median_seconds;
  std::map<std::string, double> peak_bytes;  // the largest over the repetitions
  double total = 0.0, limit = 0.0, run_peak = 0.0, limit_peak = 0.0;
};

// Median seconds per phase over the runs, in the first run's order.
std::vector<std::pair<std::string, double>> median_phases(const std::vector<Run>& runs) {
  std::vector<std::pair<std::string, double>> out;
  for (const auto& [phase, s0] : runs.front().seconds) {
    std::vector<double> v;
    for (const Run& r : runs)
      for (const auto& [p, s] : r.seconds)
        if (p == phase)
          v.push_back(s);
    out.emplace_back(phase, median(v));
  }
  return out;
}

Row summarize(const std::string& model, const std::vector<Run>& runs) {
  Row row{model, runs.front(), median_phases(runs), {}, 0, 0, 0, 0};
  std::vector<double> totals, limits;
  for (const Run& r : runs) {
    totals.push_back(total_without_writing(r));
    limits.push_back(r.limit_seconds);
    row.run_peak = std::max(row.run_peak, r.run_peak_bytes);
    row.limit_peak = std::max(row.limit_peak, r.limit_peak_bytes);
    for (const auto& [p, b] : r.peak_bytes)
      row.peak_bytes[p] = std::max(row.peak_bytes[p], b);
  }
  row.total = median(totals);
  row.limit = median(limits);
  return row;
}

double mib(double bytes) {
  return bytes / (1024.0 * 1024.0);
}

void print_row(const Row& r) {
  fmt::print("\n{} model, {} blocks, {} interfaces, {} unknowns", r.model, r.first.blocks,
             r.first.interfaces, r.first.unknowns);
  if (r.model != "elastic")
    fmt::print(
        ", {} yield points, {} increments, largest LCP {} rows{}, K condensed {} times ({} "
        "regions), a reserve zone used {} times (last zone {} blocks)",
        r.first.yield_points, r.first.increments, r.first.lcp_rows_max,
        r.first.collapsed ? ", collapsed" : "", r.first.condensations, r.first.regions,
        r.first.reserve_switches, r.first.zone_blocks);
  fmt::print("\n  {:<34} {:>10} {:>10}\n", "phase", "median s", "RSS peak");
  for (const auto& [phase, s] : r.median_seconds) {
    const auto peak = r.peak_bytes.find(phase);
    fmt::print(
        "  {:<34} {:>10.3f} {:>10}\n", phase, s,
        peak == r.peak_bytes.end() ? std::string("-") : fmt::format("{:.0f}", mib(peak->second)));
  }
  fmt::print("  {:<34} {:>10.3f} {:>10.0f}\n", "whole analysis (without writing)", r.total,
             mib(r.run_peak));
  fmt::print("  {:<34} {:>10.3f} {:>10.0f}\n", "physical limit (K + CHOLMOD alone)", r.limit,
             mib(r.limit_peak));
  fmt::print("  (RSS peak: the process's resident set in MiB; the last two rows: its growth)\n");
  // A growth under 1 MiB (the smallest models) is the allocator's noise: no memory ratio then.
  fmt::print("  ratio to the limit: time {:.2f}, memory {}\n", r.total / r.limit,
             mib(r.limit_peak) >= 1.0 ? fmt::format("{:.2f}", r.run_peak / r.limit_peak) : "-");
}

nlohmann::json to_json(const Row& r) {
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& [phase, s] : r.median_seconds) {
    nlohmann::json p = {{"phase", phase}, {"median_seconds", s}};
    if (const auto peak = r.peak_bytes.find(phase); peak != r.peak_bytes.end())
      p["peak_bytes"] = peak->second;
    phases.push_back(p);
  }
  return {{"model", r.model},
          {"blocks", r.first.blocks},
          {"interfaces", r.first.interfaces},
          {"unknowns", r.first.unknowns},
          {"yield_points", r.first.yield_points},
          {"increments", r.first.increments},
          {"lcp_rows_max", r.first.lcp_rows_max},
          {"collapsed", r.first.collapsed},
          {"condensations", r.first.condensations},
          {"reserve_switches", r.first.reserve_switches},
          {"regions", r.first.regions},
          {"zone_blocks", r.first.zone_blocks},
          {"phases", phases},
          {"whole_seconds", r.total},
          {"limit_seconds", r.limit},
          {"time_ratio", r.total / r.limit},
          {"whole_peak_bytes", r.run_peak},
          {"limit_peak_bytes", r.limit_peak},
          {"memory_ratio", mib(r.limit_peak) >= 1.0 ? nlohmann::json(r.run_peak / r.limit_peak)
                                                    : nlohmann::json()}};
}

void write_plots(const std::vector<Row>& rows, const fs::path& folder) {
  fs::create_directories(folder);
  LinePlot time{
      "bimrock bench: time of a whole analysis", "blocks", "seconds (median)", {}, true, true};
  LinePlot memory{"bimrock bench: peak memory", "blocks", "MiB", {}, true, true};
  for (const std::string model : {"elastic", "plastic", "nonassociated"}) {
    PlotSeries t{model + " analysis", {}, {}}, l{model + ": CHOLMOD alone", {}, {}};
    PlotSeries m{model + " analysis", {}, {}}, ml{model + ": CHOLMOD alone", {}, {}};
    for (const Row& r : rows) {
      if (r.model != model)
        continue;
      for (PlotSeries* s : {&t, &l, &m, &ml})
        s->x.push_back(r.first.blocks);
      t.y.push_back(r.total);
      l.y.push_back(r.limit);
      m.y.push_back(mib(r.run_peak));
      ml.y.push_back(mib(r.limit_peak));
    }
    if (t.x.empty())
      continue;
    time.series.insert(time.series.end(), {t, l});
    memory.series.insert(memory.series.end(), {m, ml});
  }
  write_line_plot(time, folder / "bench_time");
  write_line_plot(memory, folder / "bench_memory");
}

}  // namespace

int run_bench(const BenchOptions& options) {
  const fs::path scratch = fs::temp_directory_path() / fmt::format("bimrock-bench-{}", ::getpid());
  fs::create_directories(scratch);
  set_memory_tracking(true);  // each phase's peak resident memory, in the timings
  fmt::print("bimrock bench: {} hardware threads, {} repetitions, medians; SI units\n",
             std::thread::hardware_concurrency(), options.repetitions);
  std::vector<Row> rows;
  for (const std::string& model : options.models) {
    const std::vector<int>& sizes =
        model == "elastic" ? options.elastic_sizes : options.plastic_sizes;
    for (int n : sizes) {
      std::vector<Run> runs;
      // "nonassociated": the plastic model with joints of no dilation.
      const JointFlow flow =
          model == "nonassociated" ? JointFlow::no_dilation : JointFlow::associated;
      for (int rep = 0; rep < options.repetitions; ++rep)
        runs.push_back(model == "elastic" ? run_elastic(n, scratch)
                                          : run_plastic(n, options.increments, flow, scratch));
      rows.push_back(summarize(model, runs));
      print_row(rows.back());
      std::fflush(stdout);
    }
  }
  fs::remove_all(scratch);
  if (!options.json.empty()) {
    nlohmann::json j = {{"hardware_threads", std::thread::hardware_concurrency()},
                        {"repetitions", options.repetitions},
                        {"rows", nlohmann::json::array()}};
    for (const Row& r : rows)
      j["rows"].push_back(to_json(r));
    std::ofstream(options.json) << j.dump(2) << '\n';
  }
  if (!options.plot.empty())
    write_plots(rows, options.plot);
  return 0;
}

}  // namespace bimrock
