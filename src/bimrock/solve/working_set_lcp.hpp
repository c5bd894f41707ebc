#pragma once
/// @file Lemke on a working set of rows (constraint generation). In an increment near collapse
/// the LCP has thousands of candidate rows of which a few hundred become active, and the
/// active-set method may fail there (its intermediate active sets can be singular or cycle).
/// Dense Lemke on the whole matrix then costs O(m^3) and every column of M. Instead: solve the
/// sub-LCP of a working set W (the rows that were violated or active) with Lemke, z = 0 off W;
/// if w = M z + q >= 0 on every other row as well, z solves the whole LCP (the conditions off W
/// are exactly w_i >= 0 with z_i = 0); else add the rows with w_i < 0 to W and solve again.
///
/// A sub-LCP without a solution does not by itself prove that the whole one has none (a
/// solution may use rows off W). For symmetric M (associated flow) Lemke's ray r_W extended by
/// zeros is checked as a certificate on the whole LCP (r >= 0, M^T r <= 0 on every row,
/// q . r < 0, Farkas), and only a certified ray is answered no_solution. Otherwise the answer is
/// solved or a failure (iteration_limit, numerical_failure): then ask Lemke on the whole LCP.
#include <vector>

#include <bimrock/solve/lcp_columns.hpp>
#include <bimrock/solve/lemke.hpp>

namespace bimrock {

struct WorkingSetOptions {
  int max_rounds = 30;
  /// The result must satisfy LcpResiduals::worst_relative() <= accuracy on the whole LCP.
  double accuracy = 1e-9;
};

/// @param initial the first working set (any order, duplicates allowed); the rows with
///        q_i < 0 are always added.
/// @return solved, no_solution with a certified ray, or iteration_limit / numerical_failure.
///         `steps` counts Lemke's pivots over all rounds.
[[nodiscard]] LcpResult solve_on_working_set(LcpColumns& problem,
                                             const std::vector<Eigen::Index>& initial, Lemke& lemke,
                                             const WorkingSetOptions& options = {});

}  // namespace bimrock
