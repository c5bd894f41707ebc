#include <bimrock/solve/factor_memory.hpp>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <unordered_map>
#include <vector>

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <SuiteSparse_config.h>

namespace bimrock {

namespace {

struct Mapping {
  void* base = nullptr;
  std::size_t bytes = 0;  // mapped length, whole pages
};

// The large blocks handed out (pointer -> mapped length), and the freed ones kept. One lock:
// CHOLMOD allocates from the calling thread, and large blocks are few.
struct Registry {
  std::mutex mutex;
  std::unordered_map<void*, std::size_t> live;
  std::vector<Mapping> kept;
  std::atomic<bool> recycling{true};  // read before the lock: small blocks never take it
  FactorMemoryStats stats;
};

Registry& registry() {
  // Never destroyed: a factor held by a static object may be freed after static destructors.
  static Registry* const r = new Registry;
  return *r;
}

std::size_t whole_pages(std::size_t bytes) {
  static const auto page = static_cast<std::size_t>(sysconf(_SC_PAGESIZE));
  return (bytes + page - 1) / page * page;
}

// A large block of `bytes`: the kept mapping nearest its size within a factor of two, resized,
// or a new mapping. `reused` gets how many of its leading bytes hold old data (0: all zero).
void* map_large(Registry& r, std::size_t bytes, std::size_t& reused) {
  const std::size_t want = whole_pages(bytes);
  auto best = r.kept.end();
  for (auto it = r.kept.begin(); it != r.kept.end(); ++it) {
    const bool fits = it->bytes >= want / 2 && it->bytes <= 2 * want;
    const auto gap = [want](const Mapping& m) {
      return m.bytes > want ? m.bytes - want : want - m.bytes;
    };
    if (fits && (best == r.kept.end() || gap(*it) < gap(*best)))
      best = it;
  }
  void* p = MAP_FAILED;
  reused = 0;
  if (best != r.kept.end()) {
    p = mremap(best->base, best->bytes, want, MREMAP_MAYMOVE);
    if (p == MAP_FAILED)
      munmap(best->base, best->bytes);
    else
      reused = std::min(best->bytes, want);
    r.stats.kept_bytes -= static_cast<std::int64_t>(best->bytes);
    r.kept.erase(best);
  }
  if (p == MAP_FAILED) {
    p = mmap(nullptr, want, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (p == MAP_FAILED)
      return nullptr;
    ++r.stats.mapped;
  } else {
    ++r.stats.reused;
  }
  r.live.emplace(p, want);
  return p;
}

}  // namespace

void* factor_malloc(std::size_t bytes) {
  Registry& r = registry();
  if (bytes < kLargeFactorBlock || !r.recycling)
    return std::malloc(bytes);
  const std::lock_guard<std::mutex> lock(r.mutex);
  std::size_t reused = 0;
  return map_large(r, bytes, reused);
}

void* factor_calloc(std::size_t count, std::size_t size) {
  if (size != 0 && count > static_cast<std::size_t>(-1) / size)
    return nullptr;
  const std::size_t bytes = count * size;
  Registry& r = registry();
  if (bytes < kLargeFactorBlock || !r.recycling)
    return std::calloc(count, size);
  const std::lock_guard<std::mutex> lock(r.mutex);
  std::size_t reused = 0;
  void* p = map_large(r, bytes, reused);
  if (p)  // pages beyond the kept ones are fresh, and zero
    std::memset(p, 0, std::min(reused, bytes));
  return p;
}

void* factor_realloc(void* block, std::size_t bytes) {
  if (!block)
    return factor_malloc(bytes);
  Registry& r = registry();
  std::unique_lock<std::mutex> lock(r.mutex);
  const auto it = r.live.find(block);
  if (it != r.live.end()) {  // a large block: resized in place or moved, its pages kept
    const std::size_t want = whole_pages(std::max<std::size_t>(bytes, 1));
    void* p = mremap(block, it->second, want, MREMAP_MAYMOVE);
    if (p == MAP_FAILED)
      return nullptr;  // the block stays as it was, as realloc's contract says
    r.live.erase(it);
    r.live.emplace(p, want);
    return p;
  }
  lock.unlock();
  if (bytes < kLargeFactorBlock || !r.recycling)
    return std::realloc(block, bytes);
  void* p = factor_malloc(bytes);  // glibc's block grows into a large one
  if (p) {
    std::memcpy(p, block, std::min(malloc_usable_size(block), bytes));
    std::free(block);
  }
  return p;
}

void factor_free(void* block) {
  if (!block)
    return;
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  const auto it = r.live.find(block);
  if (it == r.live.end()) {
    std::free(block);
    return;
  }
  if (!r.recycling) {
    munmap(block, it->second);
    r.live.erase(it);
    return;
  }
  r.kept.push_back({block, it->second});
  r.stats.kept_bytes += static_cast<std::int64_t>(it->second);
  r.live.erase(it);
  if (r.kept.size() > static_cast<std::size_t>(kKeptFactorBlocks)) {
    // The smallest goes: a factor's values must not make way for a transpose's workspace.
    const auto smallest =
        std::min_element(r.kept.begin(), r.kept.end(),
                         [](const Mapping& a, const Mapping& b) { return a.bytes < b.bytes; });
    munmap(smallest->base, smallest->bytes);
    r.stats.kept_bytes -= static_cast<std::int64_t>(smallest->bytes);
    r.kept.erase(smallest);
  }
}

void install_factor_memory() {
  static std::once_flag once;
  std::call_once(once, [] {
    SuiteSparse_config.malloc_func = factor_malloc;
    SuiteSparse_config.calloc_func = factor_calloc;
    SuiteSparse_config.realloc_func = factor_realloc;
    SuiteSparse_config.free_func = factor_free;
  });
}

void recycle_factor_memory(bool on) {
  if (!on)
    release_kept_factor_memory();
  registry().recycling = on;
}

void release_kept_factor_memory() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  for (const Mapping& m : r.kept)
    munmap(m.base, m.bytes);
  r.kept.clear();
  r.stats.kept_bytes = 0;
}

FactorMemoryStats factor_memory_stats() {
  Registry& r = registry();
  const std::lock_guard<std::mutex> lock(r.mutex);
  return r.stats;
}

}  // namespace bimrock
