#pragma once
/// @file The check that a vector of multipliers proves a load-controlled increment unsolvable
/// (Farkas), on the increment's own LCP: M = N - C K^-1 Phi applied through K's factor, never
/// formed.
#include <optional>

#include <Eigen/Core>

#include <bimrock/analysis/increment.hpp>
#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/solve/increment_lcp.hpp>

namespace bimrock {

/// Whether r (>= 0, largest entry 1) certifies that the increment's LCP (rows `sys`, `lcp` as
/// the solver got it) has no solution: M^T r <= 0 and q . r < 0 (certifies_infeasibility in
/// solve/lcp.hpp). Where it does, the least fraction of the step from which on it does
/// (certified_from; 1 where the LCP holds no load part); else none.
std::optional<double> certified_step_fraction(const StageContext& ctx, const YieldSystem& sys,
                                              const IncrementLcp& lcp, const Eigen::VectorXd& r);

}  // namespace bimrock
