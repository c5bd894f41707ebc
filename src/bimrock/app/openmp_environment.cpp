#include "bimrock/app/openmp_environment.hpp"

#include <cstdlib>

#include <unistd.h>

namespace bimrock {

namespace {

// Sets `name` to `value` unless the user has set it; true if it did.
bool set_default(const char* name, const char* value) {
  return std::getenv(name) == nullptr && setenv(name, value, 1) == 0;
}

}  // namespace

void ensure_openmp_environment(char** argv) {
  const bool limit = set_default("OMP_THREAD_LIMIT", "1");
  const bool policy = set_default("OMP_WAIT_POLICY", "passive");
  if (limit || policy)
    execv("/proc/self/exe", argv);  // returns only on failure
}

}  // namespace bimrock
