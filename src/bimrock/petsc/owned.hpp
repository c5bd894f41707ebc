#pragma once
/// @file A PETSc object owned by a scope: PETSc's objects are handles, each destroyed by a
/// function of its type (MatDestroy, ISDestroy, ...), in every case, exceptions too.
#include <petscsys.h>

namespace bimrock {

template <class Handle, PetscErrorCode (*destroy)(Handle*)>
class Owned {
 public:
  Owned() = default;
  ~Owned() { destroy(&handle_); }
  Owned(const Owned&) = delete;
  Owned& operator=(const Owned&) = delete;

  /// Where a PETSc call that creates the object writes its handle.
  [[nodiscard]] Handle* out() { return &handle_; }
  [[nodiscard]] Handle get() const { return handle_; }

 private:
  Handle handle_ = nullptr;
};

}  // namespace bimrock
