#pragma once
/// @file PETSc, and MPI under it, for the length of a command (docs/parallel.md). Every process
/// of an `mpirun -n N bimrock ...` holds one; PETSc reads its own options from the environment
/// variable PETSC_OPTIONS (e.g. "-pc_type hypre -ksp_monitor").

namespace bimrock {

class PetscRuntime {
 public:
  PetscRuntime();
  ~PetscRuntime();
  PetscRuntime(const PetscRuntime&) = delete;
  PetscRuntime& operator=(const PetscRuntime&) = delete;

  /// This process's number among the run's processes (0 writes the results).
  [[nodiscard]] int rank() const { return rank_; }
  /// How many processes the run has (mpirun -n N).
  [[nodiscard]] int ranks() const { return ranks_; }
  /// The sum of `x` over the processes, on every process (each must call it).
  [[nodiscard]] double sum(double x) const;

 private:
  int rank_ = 0;
  int ranks_ = 1;
};

}  // namespace bimrock
