# Every dependency is a Debian package (see the Makefile's DEBIAN_PACKAGES).
include(${CMAKE_CURRENT_LIST_DIR}/bimrockDependencies.cmake)
# The command's only.
find_package(CLI11 REQUIRED)
