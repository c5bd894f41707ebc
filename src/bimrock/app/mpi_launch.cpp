#include "bimrock/app/mpi_launch.hpp"

#include <cstdlib>
#include <initializer_list>

namespace bimrock {
namespace {

// The first of `names` set to a whole number, or `otherwise`.
int from_environment(std::initializer_list<const char*> names, int otherwise) {
  for (const char* name : names) {
    const char* value = std::getenv(name);
    if (value == nullptr || *value == '\0')
      continue;
    char* end = nullptr;
    const long n = std::strtol(value, &end, 10);
    if (*end == '\0' && n >= 0 && n < (1L << 30))
      return static_cast<int>(n);
  }
  return otherwise;
}

}  // namespace

int launched_processes() {
  return from_environment({"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}, 1);
}

int launched_rank() {
  return from_environment({"OMPI_COMM_WORLD_RANK", "PMI_RANK"}, 0);
}

}  // namespace bimrock
