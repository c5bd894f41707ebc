#include "bimrock/app/bench_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <bimrock/analysis/memory_probe.hpp>

#include "bimrock/app/bench_run.hpp"
#include "bimrock/app/bench_table.hpp"

namespace bimrock {

namespace fs = std::filesystem;
using bench::print_row;
using bench::Row;
using bench::Run;
using bench::run_elastic;
using bench::run_plastic;
using bench::summarize;
using bench::to_json;
using bench::write_plots;

namespace {

// The threads OpenBLAS runs the factorizations' dense kernels on, as the environment limits them
// (docs/performance.md, "Threads"): the only parallel work of a run.
std::string blas_threads() {
  const char* limit = std::getenv("OPENBLAS_NUM_THREADS");
  return limit != nullptr ? std::string(limit)
                          : fmt::format("{} (all)", std::thread::hardware_concurrency());
}

}  // namespace

int run_bench(const BenchOptions& options) {
  const fs::path scratch = fs::temp_directory_path() / fmt::format("bimrock-bench-{}", ::getpid());
  fs::create_directories(scratch);
  set_memory_tracking(true);  // each phase's peak resident memory, in the timings
  fmt::print(
      "bimrock bench: CHOLMOD on 1 process, {} hardware threads, BLAS threads {}, {} "
      "repetitions, medians; SI units\n",
      std::thread::hardware_concurrency(), blas_threads(), options.repetitions);
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
        runs.push_back(model == "elastic"
                           ? run_elastic(n, scratch)
                           : run_plastic(n, options.increments, flow, model == "fos", scratch));
      rows.push_back(summarize(model, runs));
      print_row(rows.back());
      std::fflush(stdout);
    }
  }
  fs::remove_all(scratch);
  if (!options.json.empty()) {
    nlohmann::json j = {{"solver", "cholmod"},
                        {"processes", 1},
                        {"hardware_threads", std::thread::hardware_concurrency()},
                        {"blas_threads", blas_threads()},
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
