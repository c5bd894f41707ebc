#include "bimrock/app/bench_table.hpp"

#include <algorithm>
#include <string>

#include <fmt/core.h>

#include <bimrock/io/line_plot.hpp>

namespace bimrock::bench {

namespace {

namespace fs = std::filesystem;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n == 0 ? 0.0 : n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double total_without_writing(const Run& r) {
  double t = 0.0;
  for (const auto& [phase, s] : r.seconds)
    if (phase != "write results" && phase.front() != '(')
      t += s;
  return t;
}

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

double mib(double bytes) {
  return bytes / (1024.0 * 1024.0);
}

}  // namespace

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
    row.first.all_processes_peak_bytes =
        std::max(row.first.all_processes_peak_bytes, r.all_processes_peak_bytes);
  }
  row.total = median(totals);
  row.limit = median(limits);
  return row;
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
  if (r.limit > 0.0)
    fmt::print("  {:<34} {:>10.3f} {:>10.0f}\n", "physical limit (K + CHOLMOD alone)", r.limit,
               mib(r.limit_peak));
  else
    fmt::print("  {:<34} {:>10} {:>10}\n", "physical limit (K + CHOLMOD alone)", "-", "-");
  fmt::print("  (RSS peak: the process's resident set in MiB; the last two rows: its growth)\n");
  if (!r.first.method.empty()) {
    // The elastic model's solve has iterations and a residual; the plastic models' direct
    // factor has neither.
    const std::string solve = r.first.iterations > 0
                                  ? fmt::format(", {} iterations, relative residual {:.2e}",
                                                r.first.iterations, r.first.relative_residual)
                                  : std::string();
    fmt::print(
        "  PETSc: {} on {} process{}{}; all processes' resident sets {:.0f} MiB at their peaks\n",
        r.first.method, r.first.processes, r.first.processes == 1 ? "" : "es", solve,
        mib(r.first.all_processes_peak_bytes));
  }
  // A growth under 1 MiB (the smallest models) is the allocator's noise: no memory ratio then.
  if (r.limit > 0.0)
    fmt::print("  ratio to the limit: time {:.2f}, memory {}\n", r.total / r.limit,
               mib(r.limit_peak) >= 1.0 ? fmt::format("{:.2f}", r.run_peak / r.limit_peak) : "-");
  for (const auto& [phase, s] : r.median_seconds) {
    if (phase == "(factor of safety)")
      fmt::print("  factor of safety: {:.3f} s, {:.2f} times the rest of the analysis\n", s,
                 s / (r.total - s));
  }
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
          {"method", r.first.method.empty() ? nlohmann::json() : nlohmann::json(r.first.method)},
          {"processes", r.first.processes},
          {"iterations", r.first.iterations},
          {"relative_residual", r.first.relative_residual},
          {"all_processes_peak_bytes", r.first.all_processes_peak_bytes},
          {"phases", phases},
          {"whole_seconds", r.total},
          {"limit_seconds", r.limit},
          {"time_ratio", r.limit > 0.0 ? nlohmann::json(r.total / r.limit) : nlohmann::json()},
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
  for (const std::string model : {"elastic", "plastic", "nonassociated", "fos"}) {
    PlotSeries t{model + " analysis", {}, {}}, l{model + ": CHOLMOD alone", {}, {}};
    PlotSeries m{model + " analysis", {}, {}}, ml{model + ": CHOLMOD alone", {}, {}};
    for (const Row& r : rows) {
      if (r.model != model)
        continue;
      for (PlotSeries* s : {&t, &m})
        s->x.push_back(r.first.blocks);
      t.y.push_back(r.total);
      m.y.push_back(mib(r.run_peak));
      if (r.limit <= 0.0)
        continue;  // not measured (--no-limit)
      for (PlotSeries* s : {&l, &ml})
        s->x.push_back(r.first.blocks);
      l.y.push_back(r.limit);
      ml.y.push_back(mib(r.limit_peak));
    }
    if (t.x.empty())
      continue;
    time.series.push_back(t);
    memory.series.push_back(m);
    if (!l.x.empty()) {
      time.series.push_back(l);
      memory.series.push_back(ml);
    }
  }
  write_line_plot(time, folder / "bench_time");
  write_line_plot(memory, folder / "bench_memory");
}

}  // namespace bimrock::bench
