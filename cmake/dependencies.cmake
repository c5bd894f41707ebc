# Every dependency is a Debian package (see the Makefile's DEBIAN_PACKAGES).
include(${CMAKE_CURRENT_LIST_DIR}/bimrockDependencies.cmake)
# The command's only.
find_package(CLI11 REQUIRED)
# Optional: the PETSc backend (src/bimrock/petsc, docs/parallel.md), built where Debian's PETSc
# (libpetsc-real-dev, with Open MPI) is installed and BIMROCK_WITH_PETSC is on.
if(BIMROCK_WITH_PETSC)
  find_package(PkgConfig REQUIRED)
  pkg_check_modules(PETSC IMPORTED_TARGET PETSc)
  set(MPI_CXX_SKIP_MPICXX ON)  # MPI's C interface, from C++
  find_package(MPI COMPONENTS CXX)
  if(PETSC_FOUND AND MPI_CXX_FOUND)
    message(STATUS "PETSc ${PETSC_VERSION}: the PETSc backend is built")
  else()
    message(STATUS "PETSc not found: the PETSc backend is not built")
  endif()
endif()
