#pragma once
// CHOLMOD runs OpenMP loops (libgomp) beside OpenBLAS's own threads. libgomp lets its idle
// threads spin by default, and on a machine with few cores they take the core that the main
// thread's work needs between factorizations. Measured on 2 cores
// (`bimrock bench --models elastic --elastic-sizes 10000`): whole elastic run 1.12 s -> 0.77 s,
// factorization 0.81 s -> 0.69 s with OMP_WAIT_POLICY=passive. libgomp reads the policy once,
// when it loads, so the process sets it and starts itself again before anything else.

namespace bimrock {

/// Unless OMP_WAIT_POLICY is set (the user's choice wins), sets it to `passive` and replaces the
/// process by a fresh start of the same executable with the same arguments. Returns only if that
/// is not needed or not possible (then the run goes on with libgomp's default).
void ensure_passive_openmp_wait(char** argv);

}  // namespace bimrock
