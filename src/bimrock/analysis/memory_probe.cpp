#include <bimrock/analysis/memory_probe.hpp>

#include <atomic>
#include <fstream>
#include <string>

#include <malloc.h>

#include <bimrock/solve/factor_memory.hpp>

namespace bimrock {

namespace {

// A "Key:   123 kB" line of /proc/self/status, in bytes.
std::int64_t status_field(const std::string& key) {
  std::ifstream in("/proc/self/status");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(key + ":", 0) == 0)
      return std::stoll(line.substr(key.size() + 1)) * 1024;
  }
  return -1;
}

std::atomic<bool> tracking{false};

}  // namespace

void set_memory_tracking(bool on) {
  tracking = on;
}

bool memory_tracking() {
  return tracking;
}

void reset_peak_memory() {
  std::ofstream clear("/proc/self/clear_refs");
  if (clear)
    clear << "5";
}

std::int64_t peak_memory_bytes() {
  return status_field("VmHWM");
}

void release_free_memory() {
  release_kept_factor_memory();
  malloc_trim(0);
}

std::int64_t current_memory_bytes() {
  return status_field("VmRSS");
}

}  // namespace bimrock
