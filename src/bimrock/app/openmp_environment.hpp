#pragma once
// CHOLMOD (SuiteSparse 5) runs small OpenMP loops (libgomp) inside every supernode of a
// factorization, with a team size fixed when it was compiled (four threads), whatever the
// machine has; OpenBLAS has its own threads for the dense work, which is where the parallelism
// pays. On 2 cores each of those loops woke three threads that the main thread then waited for:
// a 10^4-block plastic run made 3 million context switches and spent half of its CPU time in
// the kernel. OMP_THREAD_LIMIT=1 makes those loops serial: that run 52.7 s -> 43.7 s, CHOLMOD alone
// on its K 0.40 s -> 0.27 s (medians of 3, `bimrock bench --models plastic --plastic-sizes 10000`,
// docs/performance.md). Where a team does start (a user's higher limit),
// OMP_WAIT_POLICY=passive keeps its idle threads off the cores the main thread needs (elastic
// 10^4 blocks: 1.12 s -> 0.77 s). libgomp reads both once, when it loads, so the process sets
// them and starts itself again before anything else.

namespace bimrock {

/// Sets OMP_THREAD_LIMIT=1 and OMP_WAIT_POLICY=passive where they are not set (the user's choice
/// wins) and, if it set either, replaces the process by a fresh start of the same executable
/// with the same arguments. Returns only if that is not needed or not possible (then the run
/// goes on with libgomp's defaults).
void ensure_openmp_environment(char** argv);

}  // namespace bimrock
