#include "bimrock/app/bench_command.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <thread>

#include <unistd.h>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <bimrock/analysis/memory_probe.hpp>
#include <bimrock/model/errors.hpp>
#ifdef BIMROCK_WITH_PETSC
#include <bimrock/petsc/distributed_factor.hpp>
#include <bimrock/petsc/elastic_solve.hpp>
#include <bimrock/petsc/runtime.hpp>
#endif

#include "bimrock/app/bench_run.hpp"
#include "bimrock/app/bench_table.hpp"

namespace bimrock {

namespace fs = std::filesystem;
using bench::ElasticSolve;
using bench::print_row;
using bench::Row;
using bench::Run;
using bench::run_elastic;
using bench::run_plastic;
using bench::RunSettings;
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

// The runs of every model and size, printed as they end (by the first process only).
std::vector<Row> run_all(const BenchOptions& options, const fs::path& scratch,
                         const ElasticSolve& elastic, const RunSettings& settings) {
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
        runs.push_back(model == "elastic" ? run_elastic(n, scratch, elastic, settings)
                                          : run_plastic(n, options.increments, flow, model == "fos",
                                                        scratch, settings));
      rows.push_back(summarize(model, runs));
      if (settings.first_process) {
        print_row(rows.back());
        std::fflush(stdout);
      }
    }
  }
  return rows;
}

void write_outputs(const BenchOptions& options, const std::vector<Row>& rows, int processes) {
  if (!options.json.empty()) {
    nlohmann::json j = {{"solver", options.solver},
                        {"processes", processes},
                        {"hardware_threads", std::thread::hardware_concurrency()},
                        {"blas_threads", blas_threads()},
                        {"repetitions", options.repetitions},
                        {"rows", nlohmann::json::array()}};
    for (const Row& r : rows)
      j["rows"].push_back(to_json(r));
    std::ofstream out(options.json);  // checked writable before the runs
    out << j.dump(2) << '\n';
    if (!out)
      throw std::runtime_error(fmt::format("bench: could not write {}", options.json));
  }
  if (!options.plot.empty())
    write_plots(rows, options.plot);
}

// The models on the PETSc backend, on every process of an MPI run; the first prints and writes
// (docs/parallel.md).
int run_bench_on_petsc([[maybe_unused]] const BenchOptions& options,
                       [[maybe_unused]] const fs::path& scratch) {
#ifdef BIMROCK_WITH_PETSC
  const PetscRuntime petsc;
  const bool first = petsc.rank() == 0;
  if (first)
    fmt::print(
        "bimrock bench: PETSc on {} process{}, {} hardware threads, BLAS threads {}, {} "
        "repetitions, medians; SI units\n",
        petsc.ranks(), petsc.ranks() == 1 ? "" : "es", std::thread::hardware_concurrency(),
        blas_threads(), options.repetitions);
  const ElasticSolve solve = [&petsc](const Model& model, Run& run) {
    PetscSolveReport report;
    ElasticSolution s = solve_elastic_with_petsc(model, report);
    run.method = report.method;
    run.processes = report.ranks;
    run.iterations = report.iterations;
    run.relative_residual = report.relative_residual;
    // Every process's peak so far (its model, K and share of PETSc's objects) added up.
    run.all_processes_peak_bytes = petsc.sum(static_cast<double>(peak_memory_bytes()));
    return s;
  };
  const RunSettings settings{.limit = options.limit,
                             .first_process = first,
                             .stiffness = distributed_factorization,
                             .stiffness_method = "K by MUMPS",
                             .processes = petsc.ranks(),
                             .sum_over_processes = [&petsc](double x) { return petsc.sum(x); }};
  const std::vector<Row> rows = run_all(options, scratch, solve, settings);
  if (first)
    write_outputs(options, rows, petsc.ranks());
  return 0;
#else
  throw InputError("bimrock bench", 0, "--solver petsc",
                   "this bimrock was built without PETSc (install libpetsc-real-dev and "
                   "rebuild; docs/parallel.md)");
#endif
}

}  // namespace

int run_bench(const BenchOptions& options) {
  if (!options.json.empty()) {
    // Its folder made as the plots' is, and the file tried before the runs: a table that cannot
    // be written is said at once, not after the work.
    const fs::path file(options.json);
    std::error_code ignored;
    if (file.has_parent_path())
      fs::create_directories(file.parent_path(), ignored);
    if (!std::ofstream(file))
      throw InputError("bimrock bench", 0, "--json", fmt::format("cannot write {}", file.string()));
  }
  const fs::path scratch = fs::temp_directory_path() / fmt::format("bimrock-bench-{}", ::getpid());
  fs::create_directories(scratch);
  struct Scratch {
    fs::path path;
    ~Scratch() { fs::remove_all(path); }
  } const cleanup{scratch};
  set_memory_tracking(true);  // each phase's peak resident memory, in the timings
  if (options.solver == "petsc")
    return run_bench_on_petsc(options, scratch);
  fmt::print(
      "bimrock bench: CHOLMOD on 1 process, {} hardware threads, BLAS threads {}, {} "
      "repetitions, medians; SI units\n",
      std::thread::hardware_concurrency(), blas_threads(), options.repetitions);
  const ElasticSolve solve = [](const Model& model, Run&) { return solve_elastic(model); };
  RunSettings settings;
  settings.limit = options.limit;
  const std::vector<Row> rows = run_all(options, scratch, solve, settings);
  write_outputs(options, rows, 1);
  return 0;
}

}  // namespace bimrock
