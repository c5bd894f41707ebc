#pragma once
/// @file CHOLMOD's large blocks, recycled. A plastic analysis factorizes K again in a new order
/// at each condensation: each new factor's values are a block of ~110 MB at 10^4 blocks (1.5 GB
/// at 10^5) that glibc maps afresh, so that its pages fault in one by one and the kernel zeroes
/// them, while the factor it replaces was freed just before. Here a freed large block keeps its
/// pages mapped and serves the next request of about its size (mremap resizes or moves a
/// mapping without touching the pages it keeps): the new factor's pages neither fault in nor
/// are zeroed again, and the peak memory stays the same.
///
/// A setting of the whole process (SuiteSparse's allocator is global, and other code in the
/// process may use SuiteSparse too), so it is never made as a side effect: the bimrock command
/// and the benchmarks call install_factor_memory() first thing, and a program that links the
/// library may. Without it CHOLMOD allocates with malloc, and the results are the same. At most
/// kKeptFactorBlocks freed blocks are kept; release_kept_factor_memory() unmaps them (at the end
/// of an analysis, and before a memory measurement).
#include <cstddef>
#include <cstdint>

namespace bimrock {

/// Routes SuiteSparse's malloc, calloc, realloc and free through the recycler (once; later
/// calls do nothing).
void install_factor_memory();

/// Unmaps the freed large blocks kept for reuse.
void release_kept_factor_memory();

/// Recycling on (the default), or off: every new block is glibc's, as in a program that installs
/// nothing (blocks recycled before are still resized and freed right). The baseline of
/// `bimrock bench`, CHOLMOD alone, is measured with it off. Turning it off releases what is kept.
void recycle_factor_memory(bool on);

/// Unmaps the kept blocks when it goes out of scope: an analysis's end, where nothing more is
/// factorized.
struct KeptFactorMemoryRelease {
  KeptFactorMemoryRelease() = default;
  KeptFactorMemoryRelease(const KeptFactorMemoryRelease&) = delete;
  KeptFactorMemoryRelease& operator=(const KeptFactorMemoryRelease&) = delete;
  ~KeptFactorMemoryRelease() { release_kept_factor_memory(); }
};

/// What the recycler did since the process started.
struct FactorMemoryStats {
  std::int64_t mapped = 0;      ///< large blocks mapped afresh
  std::int64_t reused = 0;      ///< large blocks served from a kept one
  std::int64_t kept_bytes = 0;  ///< bytes kept now, freed but mapped
};
[[nodiscard]] FactorMemoryStats factor_memory_stats();

/// The allocator itself (SuiteSparse's signatures), for tests.
void* factor_malloc(std::size_t bytes);
void* factor_calloc(std::size_t count, std::size_t size);
void* factor_realloc(void* block, std::size_t bytes);
void factor_free(void* block);

/// Blocks of at least this many bytes are mapped and recycled; smaller ones are glibc's.
inline constexpr std::size_t kLargeFactorBlock = std::size_t{4} << 20;
/// Freed large blocks kept at most, the smallest unmapped first: the last factor's values. The
/// kept blocks count in the peak memory, and each one more saves little time for its size.
inline constexpr int kKeptFactorBlocks = 1;

}  // namespace bimrock
