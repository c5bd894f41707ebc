#pragma once
// The table of `bimrock bench`: the runs of one model and size summarized (median seconds per
// phase, the largest peaks, the ratios to the physical limit), printed, as JSON, and plotted
// against the number of blocks.
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <nlohmann/json.hpp>

#include "bimrock/app/bench_run.hpp"

namespace bimrock::bench {

struct Row {
  std::string model;
  Run first;  // sizes and counts
  std::vector<std::pair<std::string, double>> median_seconds;
  std::map<std::string, double> peak_bytes;  // the largest over the repetitions
  double total = 0.0, limit = 0.0, run_peak = 0.0, limit_peak = 0.0;
};

/// The row of one model and size from its repetitions (at least one).
[[nodiscard]] Row summarize(const std::string& model, const std::vector<Run>& runs);

/// Prints the row's table on standard output.
void print_row(const Row& r);

[[nodiscard]] nlohmann::json to_json(const Row& r);

/// bench_time.png/svg and bench_memory.png/svg in `folder`: time and memory against blocks.
void write_plots(const std::vector<Row>& rows, const std::filesystem::path& folder);

}  // namespace bimrock::bench
