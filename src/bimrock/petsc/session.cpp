#include <bimrock/petsc/session.hpp>

#include <stdexcept>
#include <string>

#include <petscsys.h>

namespace bimrock {

PetscSession::PetscSession() {
  if (PetscInitializeNoArguments() != 0)
    throw std::runtime_error("PETSc could not be initialized (is MPI usable here?)");
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank_);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks_);
}

PetscSession::~PetscSession() {
  PetscFinalize();
}

}  // namespace bimrock
