#pragma once
// A command started by an MPI launcher (mpirun -n N bimrock ...) runs in N processes. With the
// PETSc backend (--solver petsc, docs/parallel.md) they share the work; without it each would
// solve the whole case alone and write the same results, so the command refuses such a start.

namespace bimrock {

/// The processes the MPI launcher started this one with, read from what launchers set in the
/// environment (Open MPI's OMPI_COMM_WORLD_SIZE; MPICH's, Intel MPI's and Slurm's PMI_SIZE); 1
/// outside a launch.
[[nodiscard]] int launched_processes();

/// This process's number among them (0 outside a launch).
[[nodiscard]] int launched_rank();

}  // namespace bimrock
