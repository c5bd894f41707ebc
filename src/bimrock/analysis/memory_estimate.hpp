#pragma once
/// @file The peak resident memory of a run, estimated before solving (`bimrock check`): the
/// process as it stands with its model (measured), the writers' libraries, and the stiffness K
/// with its Cholesky factor L, whose size a symbolic analysis of the block graph gives in a
/// fraction of the factorization's time (in the same fill-reducing order as the run's). That is
/// the peak of an elastic run. A nonlinear run needs it too, and more as its plastic zone
/// grows (K condensed onto the zone, dense on the zone's boundary; the LCP's columns), which
/// is known only as it runs: for it, a range, up to the zone the condensation allows.
#include <cstdint>

#include <bimrock/model/model.hpp>

namespace bimrock {

struct MemoryEstimate {
  double now_bytes = 0.0;               ///< the resident set now, with the model (-1: unknown)
  std::int64_t stiffness_nonzeros = 0;  ///< of K's lower triangle
  std::int64_t factor_nonzeros = 0;     ///< of L (estimated from the block graph's factor)
  double solve_bytes = 0.0;             ///< K, its reordered copy and L
  double peak_bytes = 0.0;              ///< of an elastic run; the least of a nonlinear one
  double nonlinear_bytes = 0.0;  ///< a nonlinear run's, its plastic zone grown to the largest
};

[[nodiscard]] MemoryEstimate estimate_memory(const Model& model);

}  // namespace bimrock
