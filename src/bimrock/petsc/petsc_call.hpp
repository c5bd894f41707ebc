#pragma once
/// @file A PETSc call's error code turned into an exception naming the call. PETSc prints its
/// own message first. Where the user has set PETSC_OPTIONS, those are the likely cause (an
/// unknown method, one that does not take this matrix): an input error naming them.
#include <cstdlib>
#include <stdexcept>

#include <fmt/core.h>
#include <petscsys.h>

#include <bimrock/model/errors.hpp>

namespace bimrock {

inline void petsc_call(PetscErrorCode code, const char* call) {
  if (code == 0)
    return;
  const char* options = std::getenv("PETSC_OPTIONS");
  if (options != nullptr && *options != '\0')
    throw InputError("PETSC_OPTIONS", 0, options,
                     fmt::format("PETSc's {} failed with these options (error code {}; PETSc's "
                                 "message above): correct or unset them (docs/parallel.md)",
                                 call, code));
  throw std::runtime_error(fmt::format("PETSc: {} failed with error code {}", call, code));
}

}  // namespace bimrock
