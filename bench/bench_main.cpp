// The kernel benchmarks' entry point: Google Benchmark's, run in the OpenMP environment the
// bimrock command sets for itself, so a kernel here costs what it costs in an analysis.
#include <benchmark/benchmark.h>

#include "bimrock/app/openmp_environment.hpp"

int main(int argc, char** argv) {
  bimrock::ensure_openmp_environment(argv);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
