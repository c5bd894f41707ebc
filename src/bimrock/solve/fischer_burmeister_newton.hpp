#pragma once
/// @file A globalized semismooth Newton method for a non-symmetric increment LCP on its sparse
/// reduced tangent (De Luca, Facchinei and Kanzow 1996): the LCP is the root of
///
///   Phi_i(z) = a_i + w_i - sqrt(a_i^2 + w_i^2),   a_i = s_i z_i,   w = M z + q,
///
/// (Fischer-Burmeister; s_i = N_ii puts z_i in the units of w_i), and each step is a Newton step
/// on it, damped by a line search on the merit function |Phi|^2 / 2. The block rule of the
/// active-set method is Newton's method on min(z, w) without a merit function: near a limit load
/// of non-associated flow it swaps rows without end, and with no quadratic program behind a
/// non-symmetric M there is no projected Newton to go on with. This method lowers its merit at
/// every step, so it cannot cycle, and it converges quadratically near a regular solution.
///
/// A step's equations, with the generalized Jacobian's diagonals alpha_i = s_i (1 - a_i / r_i),
/// beta_i = 1 - w_i / r_i (r_i = |(a_i, w_i)|; both 1 - 1/sqrt(2) where r_i = 0):
///
///   alpha dz + beta (N dz - C dx) = -Phi,   S dx = Phi dz,
///
/// keep their local part per yield point, G = diag(alpha) + diag(beta) N_gg, so that
/// dz_g = G^-1 (-Phi_g + beta_g C_g dx), and dx solves the tangent
///
///   (S - sum_g Phi_g G^-1 diag(beta_g) C_g) dx = sum_g Phi_g G^-1 (-Phi_g),
///
/// which has S's pattern (one sparse LU per step, as the active-set route's). A row far from
/// yield (z_i = 0, w_i > 0) has beta_i = 0 and drops out of the tangent; a row strictly active
/// (z_i > 0, w_i = 0) has alpha_i = 0 and enters as in the active-set tangent.
#include <Eigen/Core>

#include <bimrock/solve/lcp.hpp>
#include <bimrock/solve/split_lcp_equations.hpp>

namespace bimrock {

struct FischerBurmeisterOptions {
  int max_iterations = 50;
  /// The result must satisfy LcpResiduals::worst_relative() <= accuracy.
  double accuracy = 1e-9;
};

/// Solves the LCP in its sparse parts from `start` (z >= 0; negative entries are set to 0), S
/// given by its factor. Answers solved (checked on the whole LCP, w measured with S's factor),
/// or iteration_limit / numerical_failure with the iterate of least merit (where no step lowers
/// the merit: a stationary point that is no solution, or a singular tangent; or where five steps
/// in a row lowered it by less than 10%, as it does near a point that is no solution). It never
/// proves that no solution exists: the caller's other methods decide that. `steps` counts the LU
/// factorizations of the tangent, one per iteration.
[[nodiscard]] LcpResult fischer_burmeister_newton(const SplitLcp& lcp, const SpdSolver& s,
                                                  const Eigen::VectorXd& start,
                                                  const FischerBurmeisterOptions& options = {});

}  // namespace bimrock
