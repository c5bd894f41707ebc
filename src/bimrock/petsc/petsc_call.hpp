#pragma once
/// @file A PETSc call's error code turned into an exception naming the call.
#include <stdexcept>

#include <fmt/core.h>
#include <petscsys.h>

namespace bimrock {

inline void petsc_call(PetscErrorCode code, const char* call) {
  if (code != 0)
    throw std::runtime_error(fmt::format("PETSc: {} failed with error code {}", call, code));
}

}  // namespace bimrock
