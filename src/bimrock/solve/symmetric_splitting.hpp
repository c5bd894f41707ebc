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
/// The plain iterates (y_k+1 = E z_k with z_k the inner solution) converge only linearly, and
/// near a limit load, where the left-out part couples strongly to the flow, they swap rows back
/// and forth. So they are accelerated by Anderson's method (Walker and Ni, "Anderson acceleration
/// for fixed-point iterations", SIAM J. Numer. Anal. 49, 2011) on the remainder y = E z, not on
/// z: the map y -> E LCP(q + y, B) has the same fixed points, and since y enters the inner LCP
/// only through its right-hand side, every combination of past iterates is admissible, where a
/// combination of z's would have to be projected on z >= 0 (which spoils the acceleration).
/// Each next y is the combination of the last depth + 1 images E z_k whose residuals
/// E z_k - y_k combine to the least norm. A combination can ask more of the frozen strengths
/// than any plain iterate does: where one leaves an inner LCP unsolved, or the iterations run
/// out, the splitting starts again, damped instead (after three iterates in a row that change
/// no fewer rows than the fewest so far, each moves half as far towards its inner solution as
/// before, down to a quarter: z_k+1 = z_k + omega (z^ - z_k)), which is slower but keeps its
/// iterates among the plain ones' neighbours. Its first two iterates are the accelerated run's
/// (both runs start plain), whose inner solutions it reuses.
///
/// The iterates serve only as proposals: once an iterate keeps the last one's active set, the
/// caller tries that set on the non-symmetric LCP itself (the active-set method from there, a
/// step or two, checked), and the first one that solves it ends the iteration. In the
/// accelerated run an iterate that changes at most a few rows of the last one's set is proposed
/// too, and a proposal that does not solve the LCP is a Newton step on the fixed point
/// y = E z(y): on the active set A of z(y), z depends on y linearly, and the y of that piece at
/// which y = E z is E z_N with M_AA z_N = -q_A, the multipliers of the proposal's equations (of
/// its last step, where that moved to another set). So the next remainder is E max(z_N, 0), its
/// inner LCP warm-started from the rows z_N holds positive; the step is kept only where that
/// inner LCP is solved (within a short budget) and its residual |E z - y| falls below 0.9 of the
/// one it stepped from, else the iteration goes back to the accelerated remainder, and takes no
/// Newton step for the next two iterates. Where an inner LCP has no solution (near a limit load
/// the frozen part of the yield functions, e.g. the normal stresses a joint's friction acts on,
/// can leave too little strength for the step) or no proposal solves the LCP, the method proves
/// nothing.
#include <functional>

#include <Eigen/Core>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

struct SplittingOptions {
  /// The most iterates of each of the two runs (accelerated, then damped).
  int max_iterations = 40;
  /// The past iterates Anderson's method combines besides the last (0: the plain splitting).
  int anderson_depth = 3;
  /// Where the accelerated run ends unsolved after combining iterates, the damped run.
  bool damped_after = true;
  /// The damped run: after this many iterates in a row that change no fewer rows of the active
  /// set than the fewest so far, the relaxation halves, down to least_relaxation.
  int stalled_after = 3;
  double least_relaxation = 0.25;
  /// The accelerated run's Newton steps (false: proposals only where an iterate keeps the last
  /// one's active set, and a failed one is dropped).
  bool newton = true;
  /// An iterate that changes at most this many rows of the last one's active set is proposed,
  /// and where the proposal fails, stepped from by Newton.
  Eigen::Index newton_changed_rows = 10;
  /// A Newton step is kept where its inner residual falls below this fraction of the last.
  double newton_decrease = 0.9;
  /// Iterates after a Newton step taken back before the next one.
  int newton_pause = 2;
};

struct SplittingResult {
  bool solved = false;  ///< a proposal solved the LCP (the caller's try kept the solution)
  Eigen::VectorXd z;    ///< the last inner solution (empty when the first was not solved)
  int iterations = 0;   ///< inner LCPs solved (both runs)
  int proposals = 0;    ///< active sets tried on the LCP (both runs)
};

/// E z, for the iterate z.
using SplittingRemainder = std::function<Eigen::VectorXd(const Eigen::VectorXd& z)>;
/// Solves the LCP (q, B) warm-started from the rows flagged 1 in `warm` (may be null);
/// `after_newton`: at a Newton step's remainder, which is taken back where the LCP is not
/// solved, so a short budget of iterations is enough.
using SymmetricLcpSolve = std::function<LcpResult(const Eigen::VectorXd& q,
                                                  const Eigen::VectorXd* warm, bool after_newton)>;
/// What trying an active set on the LCP (q, M) gave: whether it solved it, and otherwise the
/// multipliers of the last equations it solved (empty where it solved none).
struct ProposalOutcome {
  bool solved = false;
  Eigen::VectorXd z;
};
/// Tries the active set flagged 1 in `active` on the LCP (q, M).
using ActiveSetProposal = std::function<ProposalOutcome(const Eigen::VectorXd& active)>;

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
