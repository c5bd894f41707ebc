#pragma once
/// @file Internal to the active-set method (active_set_lcp.cpp; not part of the public API):
/// projected Newton on the quadratic program of a symmetric LCP, min 1/2 z.M z + q.z over z >= 0
/// (Bertsekas 1982), where the block rule does not converge. It lowers the objective at every
/// step, so it cannot cycle. The block rule shares its objective and iterates to choose its start.
#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/lcp.hpp>

namespace bimrock::active_set {

/// The objective of the quadratic program of a symmetric LCP, 1/2 z.M z + q.z, from w = M z + q.
[[nodiscard]] double objective(const Eigen::VectorXd& z, const Eigen::VectorXd& w,
                               const Eigen::VectorXd& q);

/// The multipliers z of a solve as an LCP iterate, where they have no negative entry: their w
/// was measured by the solve (no back-solve).
[[nodiscard]] LcpResult as_iterate(const Eigen::VectorXd& z,
                                   const ActiveSetEquations::Solution& step, int steps);

/// Projected Newton from `at`, z >= 0 measured by problem.result(), its steps counted from
/// `iteration` on (projected_newton.cpp says how it steps). The caller's `interrupt`, if any, is
/// asked as ActiveSetLcp::Interrupt says.
[[nodiscard]] LcpResult projected_newton(ActiveSetEquations& problem,
                                         const ActiveSetOptions& options, LcpResult at,
                                         int iteration, const ActiveSetLcp::Interrupt* interrupt);

}  // namespace bimrock::active_set
