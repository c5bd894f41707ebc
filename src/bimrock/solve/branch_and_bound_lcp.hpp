#pragma once
/// @file A complete method for the LCP of any matrix: depth-first branch and bound on the
/// complementarity of the pairs (z_i, w_i) over the polyhedron {z >= 0, w = M z + q >= 0}
/// (lcp_polyhedron.hpp), the enumerative method of Judice and Faustino (1988) with linear
/// programs at its nodes.
///
/// A node holds some z_i = 0 and some w_i = 0. Its LP is either empty (no solution below it) or
/// gives a vertex; a vertex with z_i w_i = 0 on every row is a solution (made exact by
/// least_norm_pivoting(), and checked on the whole problem); otherwise the pair with the largest
/// min(z_i, w_i) (each relative to its own scale) is branched: w_i = 0 (the row active) first where
/// z_i is the larger, else z_i = 0 first. Every solution lies below one leaf, so a search in which
/// every node ends empty proves that the LCP has no solution, once each empty leaf is certified
/// so by a Farkas certificate of its own (LcpPolyhedron::certified_empty: the simplex alone can
/// call a feasible node empty); an empty root gives, by Farkas' lemma, a certificate r >= 0 with
/// M^T r <= 0 and q . r < 0.
///
/// Lemke's method decides an LCP only for copositive-plus M: for non-associated flow
/// (M = N - C K^-1 Phi not symmetric) its secondary ray proves nothing, and on the degenerate
/// LCPs of cohesionless joints (every point at the apex of its yield surface, dependent rows,
/// opposite slip flows whose columns cancel) it ends on such a ray although a solution exists.
/// This method decides every LCP, in a number of nodes that can grow as 2^n: the analysis calls
/// it last, on LCPs of at most max_size rows, within a budget of nodes.
#include <utility>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

struct BranchAndBoundOptions {
  /// The search gives up (iteration_limit) after max_nodes nodes, or once its work passes
  /// max_work, counted as n^3 / 3 per node (the LP's basis factorized again) plus n^2 per
  /// simplex pivot on an LCP of n rows: a few seconds. A search that cannot end soon so ends as
  /// an unproven failure (measured: proofs of no solution take 3 000 - 5 000 nodes of ~10
  /// pivots on 60 rows, ~4e8; a 400-row node costs ~2e7). A node's LP is stopped where it
  /// would pass the budget: one LP stalled on a degenerate vertex can otherwise cost more than
  /// the whole search.
  int max_nodes = 20000;
  double max_work = 1e9;
  /// The root's LP alone may take this much (the search below it shares max_work). The root
  /// decides the LCP of a positive semi-definite M (associated flow), which has a solution
  /// exactly where that LP is feasible, and an empty root proves any LCP unsolvable; on an LCP
  /// of 1 000 - 2 000 rows it can take more than a whole search's budget.
  double max_root_work = 1e9;
  /// Larger LCPs are not searched (iteration_limit).
  Eigen::Index max_size = 1000;
  /// A solution must satisfy LcpResiduals::worst_relative() <= accuracy.
  double accuracy = 1e-9;
};

class BranchAndBoundLcp final : public LcpSolver {
 public:
  explicit BranchAndBoundLcp(BranchAndBoundOptions options = {}) : options_(std::move(options)) {}
  [[nodiscard]] std::string name() const override { return "branch-and-bound"; }
  /// solved; no_solution when the search proves there is none (with the Farkas certificate as
  /// the ray where the root LP is empty, without a ray where every leaf is, each certified);
  /// iteration_limit past max_nodes, max_work or max_size; numerical_failure where an LP failed,
  /// or a leaf found empty has no certificate, and left the search incomplete. `steps` counts the
  /// nodes. The warm start is ignored.
  [[nodiscard]] LcpResult solve(const LcpProblem& problem,
                                const Eigen::VectorXd* warm_start = nullptr) override;

 private:
  BranchAndBoundOptions options_;
};

}  // namespace bimrock
