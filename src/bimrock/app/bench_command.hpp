#pragma once
// `bimrock bench`: whole analyses of generated models (reference/reference_cases.hpp) at several
// sizes, each phase timed (median of the repetitions) with its peak memory, beside the physical
// limit measured in the same run: CHOLMOD analyze + factorize + one solve of the same K alone.
// One run is measured in bench_run.hpp, the runs summarized into the table in bench_table.hpp.
#include <string>
#include <vector>

namespace bimrock {

struct BenchOptions {
  std::vector<std::string> models = {"elastic", "plastic"};
  std::vector<int> elastic_sizes = {1000, 10000, 100000};
  std::vector<int> plastic_sizes = {100, 1000};  ///< of both plastic models
  int repetitions = 3;
  int increments = 25;  ///< of the plastic model's loading stage
  std::string json;     ///< write the table as JSON here too ("" : no)
  std::string plot;     ///< write bench_time.png/svg and bench_memory.png/svg here ("" : no)
  /// The solver: "cholmod", or "petsc" (the PETSc backend, under mpirun too: the elastic model
  /// by multigrid, the plastic ones on K factorized by MUMPS).
  std::string solver = "cholmod";
  /// Measure the physical limit beside each run (false: --no-limit, for models whose CHOLMOD
  /// factor would not fit in memory beside the run's processes).
  bool limit = true;
};

/// Runs the benchmark, prints the table; returns the process exit code.
int run_bench(const BenchOptions& options);

}  // namespace bimrock
