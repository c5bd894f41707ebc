#include <bimrock/petsc/runtime.hpp>

#include <stdexcept>
#include <string>

#include <petscsys.h>

namespace bimrock {

PetscRuntime::PetscRuntime() {
  if (PetscInitializeNoArguments() != 0)
    throw std::runtime_error("PETSc could not be initialized (is MPI usable here?)");
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks_);
}

double PetscRuntime::sum(double x) const {
  double total = 0.0;
  MPI_Allreduce(&x, &total, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
  return total;
}

PetscRuntime::~PetscRuntime() {
  PetscFinalize();
}

}  // namespace bimrock
