#pragma once
/// @file Peak resident memory of this process, per phase (Linux: /proc/self). Writing "5" to
/// /proc/self/clear_refs resets the high-water mark VmHWM, so a phase's peak is VmHWM read at
/// its end after a reset at its start. Elsewhere, or without permission, the probe reads -1.
#include <cstdint>

namespace bimrock {

/// Whether ScopedTimer records each phase's peak (timings.hpp): a setting of the process, whose
/// resident set it measures, made by benchmarks (off by default: a reset of the peak costs a walk
/// of the page tables).
void set_memory_tracking(bool on);
[[nodiscard]] bool memory_tracking();

/// Resets the peak (high-water mark) of the resident set to the current resident set.
void reset_peak_memory();

/// The peak resident set since the last reset (or the start of the process) [bytes], or -1.
[[nodiscard]] std::int64_t peak_memory_bytes();

/// Returns the heap's free memory to the system (glibc's malloc_trim, and the factors' blocks
/// kept for reuse: factor_memory.hpp), so that a growth measured from the current resident set
/// counts what the next phase needs, not what it reuses of the memory an earlier phase freed.
/// Slow on a large heap: for a benchmark's baseline, not per phase.
void release_free_memory();

/// The current resident set [bytes], or -1.
[[nodiscard]] std::int64_t current_memory_bytes();

}  // namespace bimrock
