// The kernel benchmarks' entry point: Google Benchmark's, run in the OpenMP environment the
// bimrock command sets for itself, so a kernel here costs what it costs in an analysis.
#include <malloc.h>

#include <benchmark/benchmark.h>

#include <bimrock/solve/factor_memory.hpp>

#include "bimrock/app/openmp_environment.hpp"

int main(int argc, char** argv) {
  bimrock::ensure_openmp_environment(argv);
  bimrock::install_factor_memory();  // as the command does
  // A fixed threshold for glibc's mmap (its default, 128 KiB) turns off the sliding one, which
  // rises to the largest block freed, up to 32 MiB: with it, a kernel repeated on a 10^4-block
  // model (K's arrays ~20 MB) reused warm pages while one on 10^5 blocks (~200 MB) faulted fresh
  // ones in at every iteration, and the exponents from 10^4 to 10^5 mixed the two (assembly
  // 1.18 with it, 1.01 without). Now every size pays for fresh
  // pages, as one analysis does.
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv))
    return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
