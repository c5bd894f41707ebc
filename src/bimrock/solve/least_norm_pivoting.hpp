#pragma once
/// @file Makes a point near a solution of an LCP exact: block pivoting on the active set it
/// suggests, each set's equations M_AA z_A = -q_A solved in the least-norm sense.
///
/// On the degenerate LCPs of cohesionless joints M_AA is singular wherever rows of one yield
/// point are dependent (three yield functions vanish together at the apex; at dilation 0 the
/// two slip flows are exactly opposite, and their columns of M cancel): the least-norm solution
/// still solves such a set's equations where they are consistent, where LU gives up. The point
/// may be a vertex that a complete search found complementary to round-off, or the solution of
/// a nearby LCP (the same rows with slightly perturbed flows).
#include <optional>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

/// From `near`: A = the rows with z_i the larger of the pair (z_i, w_i), each relative to its
/// own scale. `near` corrected twice by the least-norm solution of M_AA dz_A = -(M z + q)_A
/// (staying next to it), the least-norm solution from zero, or `near` itself: the first that
/// satisfies the LCP to `accuracy` (LcpResiduals::worst_relative()) is returned, solved, with
/// `steps` as its count. Where none does, the rows the correction violates join A, those it
/// takes below zero leave, and A is tried again, up to `rounds` times, or until A has grown to
/// more than 1.5 times the first round's rows and 50 more (the sets then drift away from
/// `near`). Empty where no round succeeds.
[[nodiscard]] std::optional<LcpResult> least_norm_pivoting(const LcpProblem& problem,
                                                           const Eigen::VectorXd& near,
                                                           double accuracy, int rounds, int steps);

}  // namespace bimrock
