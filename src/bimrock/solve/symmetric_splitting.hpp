#pragma once
/// @file A matrix splitting method for a non-symmetric LCP (Cottle, Pang and Stone, "The Linear
/// Complementarity Problem", 1992, chapter 5), used to find its active set: with M = B + E and B
/// symmetric, each iterate z_k+1 solves the LCP (q + E z_k, B), and a fixed point solves (q, M).
///
/// In an increment of non-associated flow, B is the LCP of the same rows with each yield
/// function's gradient along its flow (FlowRule::gradient_along_flow): C~ = Phi^T, and E carries
/// only the part of each yield function the flow does not follow (for a joint, the friction
/// term of the normal stress where the dilation is below the friction). So each iterate is an
/// increment of associated form at the normal stresses of the last one, which the symmetric
/// routes solve fast, warm-started from the last.
///
/// The iterates converge only linearly, and not at all where the left-out part couples strongly
/// to the flow (near a limit load). So they serve as proposals: once an iterate keeps the last
/// one's active set, the caller tries that set on the non-symmetric LCP itself (the active-set
/// method from there, a step or two, checked), and the first one that solves it ends the
/// iteration. Iterates that swap rows back and forth are damped. Where an inner LCP has no
/// solution (near a limit load the frozen part of the yield functions, e.g. the normal stresses
/// a joint's friction acts on, can leave too little strength for the step) or no proposal solves
/// the LCP, the method proves nothing.
#include <functional>

#include <Eigen/Core>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

struct SplittingOptions {
  int max_iterations = 40;
  /// Where this many iterates in a row change no fewer rows of the active set than the least so
  /// far, the next ones move only half as far towards their inner solutions as before, down to
  /// least_relaxation (a relaxed splitting, z_k+1 = z_k + omega (z^ - z_k)).
  int stalled_after = 3;
  double least_relaxation = 0.25;
};

struct SplittingResult {
  bool solved = false;  ///< a proposal solved the LCP (the caller's try kept the solution)
  Eigen::VectorXd z;    ///< the last inner solution (empty when the first was not solved)
  int iterations = 0;   ///< inner LCPs solved
  int proposals = 0;    ///< active sets tried on the LCP
};

/// E z, for the iterate z.
using SplittingRemainder = std::function<Eigen::VectorXd(const Eigen::VectorXd& z)>;
/// Solves the LCP (q, B) warm-started from the rows flagged 1 in `warm` (may be null).
using SymmetricLcpSolve =
    std::function<LcpResult(const Eigen::VectorXd& q, const Eigen::VectorXd* warm)>;
/// Tries the active set flagged 1 in `active` on the LCP (q, M); true: it solved it.
using ActiveSetProposal = std::function<bool(const Eigen::VectorXd& active)>;

/// Iterates from z_0 = start (warm: the rows the first inner solve starts active) until a
/// proposal solves the LCP, an inner LCP is not solved, or the iterations run out.
[[nodiscard]] SplittingResult solve_by_splitting(const Eigen::VectorXd& q,
                                                 const SplittingRemainder& remainder,
                                                 const SymmetricLcpSolve& solve_symmetric,
                                                 const ActiveSetProposal& propose,
                                                 const Eigen::VectorXd& start,
                                                 const Eigen::VectorXd* warm,
                                                 const SplittingOptions& options = {});

}  // namespace bimrock
