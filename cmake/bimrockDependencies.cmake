# The libraries' dependencies, all Debian packages: included by the build (dependencies.cmake)
# and by the installed CMake package (bimrockConfig.cmake), which must recreate the imported
# targets its exported targets link to (the hand-made ones once, whoever asks first).
find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(CGAL REQUIRED)
find_package(yaml-cpp REQUIRED)
find_package(fmt REQUIRED)
find_package(nlohmann_json 3 REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(CAIRO REQUIRED IMPORTED_TARGET GLOBAL cairo)

# SuiteSparse 5 (Debian 12) ships no CMake package: find CHOLMOD by hand.
find_path(CHOLMOD_INCLUDE_DIR cholmod.h PATH_SUFFIXES suitesparse REQUIRED)
find_library(CHOLMOD_LIBRARY cholmod REQUIRED)
# SuiteSparse's allocator hooks (solve/factor_memory.cpp) live in its config library.
find_library(SUITESPARSECONFIG_LIBRARY suitesparseconfig REQUIRED)
# UMFPACK (GPL-2.0-or-later): the sparse LU of the non-symmetric reduced tangent
# (solve/unsymmetric_tangent.cpp).
find_library(UMFPACK_LIBRARY umfpack REQUIRED)
if(NOT TARGET SuiteSparse::UMFPACK)
  add_library(SuiteSparse::UMFPACK UNKNOWN IMPORTED GLOBAL)
  set_target_properties(SuiteSparse::UMFPACK PROPERTIES
    IMPORTED_LOCATION "${UMFPACK_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SUITESPARSECONFIG_LIBRARY}")
endif()
if(NOT TARGET SuiteSparse::CHOLMOD)
  add_library(SuiteSparse::CHOLMOD UNKNOWN IMPORTED GLOBAL)
  set_target_properties(SuiteSparse::CHOLMOD PROPERTIES
    IMPORTED_LOCATION "${CHOLMOD_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${CHOLMOD_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${SUITESPARSECONFIG_LIBRARY}")
endif()

# GLPK (GPL-3.0-or-later) solves the linear programs of the complete LCP method
# (solve/lcp_polyhedron.cpp); Debian 12 ships no CMake package for it.
find_path(GLPK_INCLUDE_DIR glpk.h REQUIRED)
find_library(GLPK_LIBRARY glpk REQUIRED)
if(NOT TARGET GLPK::GLPK)
  add_library(GLPK::GLPK UNKNOWN IMPORTED GLOBAL)
  set_target_properties(GLPK::GLPK PROPERTIES
    IMPORTED_LOCATION "${GLPK_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${GLPK_INCLUDE_DIR}")
endif()
