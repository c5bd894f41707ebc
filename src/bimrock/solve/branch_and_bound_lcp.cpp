#include <bimrock/solve/branch_and_bound_lcp.hpp>

#include <algorithm>
#include <optional>
#include <vector>

#include <bimrock/solve/lcp_polyhedron.hpp>
#include <bimrock/solve/least_norm_pivoting.hpp>

namespace bimrock {
namespace {

using Index = Eigen::Index;
using Fix = LcpPolyhedron::Fix;

/// Pairs whose smaller member is below this (relative) count as complementary.
constexpr double kComplementary = 1e-10;

/// Rounds of least-norm pivoting that make a vertex complementary to round-off exact. Such a
/// vertex at a cohesionless apex has pairs with both z_i and w_i at zero to round-off (its three
/// yield functions vanish together), and the vertex alone cannot tell which of them the
/// solution needs active: an open joint point needs a slip row beside its opening row.
constexpr int kPolishRounds = 4;

}  // namespace

LcpResult BranchAndBoundLcp::solve(const LcpProblem& problem, const Eigen::VectorXd* /*warm*/) {
  check_lcp(problem);
  const Index n = problem.size();
  if (n == 0 || (problem.q.array() >= 0.0).all())
    return make_lcp_result(problem, LcpStatus::solved, Eigen::VectorXd::Zero(n), 0);
  if (n > options_.max_size)
    return make_lcp_result(problem, LcpStatus::iteration_limit, Eigen::VectorXd::Zero(n), 0);
  const double per_pivot = static_cast<double>(n) * static_cast<double>(n);
  const double per_node = per_pivot * static_cast<double>(n) / 3.0;
  LcpPolyhedron polyhedron(problem);
  std::vector<std::vector<Fix>> stack{std::vector<Fix>(static_cast<std::size_t>(n), Fix::none)};
  bool complete = true;  // every node so far decided (none failed)
  // Nodes below the root the simplex found empty and its own duals do not prove so.
  std::vector<std::vector<Fix>> empty_leaves;
  int nodes = 0;
  Eigen::VectorXd last = Eigen::VectorXd::Zero(n);
  const auto work = [&] {
    return nodes * per_node + static_cast<double>(polyhedron.pivots()) * per_pivot;
  };
  while (!stack.empty()) {
    const double budget =
        nodes == 0 ? std::max(options_.max_root_work, options_.max_work) : options_.max_work;
    if (nodes >= options_.max_nodes || work() > budget)
      return make_lcp_result(problem, LcpStatus::iteration_limit, last, nodes);
    const std::vector<Fix> fix = std::move(stack.back());
    stack.pop_back();
    // A node's LP gets what is left of the budget: one that stalls ends the search there.
    const auto pivots_left = static_cast<long>((budget - work()) / per_pivot) + 1;
    const LcpPolyhedron::Vertex v = polyhedron.vertex(fix, pivots_left);
    ++nodes;
    if (v.status == LcpPolyhedron::Status::failed) {
      complete = false;
      continue;
    }
    if (v.status == LcpPolyhedron::Status::empty) {
      if (nodes > 1) {
        if (!polyhedron.certified_by_duals(fix, v.duals))
          empty_leaves.push_back(fix);
        continue;
      }
      // The root: no z >= 0 makes w >= 0. Farkas' lemma gives the proof.
      LcpResult r = make_lcp_result(problem, LcpStatus::no_solution, last, nodes);
      const std::optional<Eigen::VectorXd> cert = polyhedron.certificate();
      const double m_max = problem.m.cwiseAbs().maxCoeff();
      if (cert && certifies_infeasibility(problem.q, *cert, problem.m.transpose() * *cert,
                                          problem.m.cwiseAbs().transpose() * *cert, m_max)) {
        r.ray = *cert;
        return r;
      }
      r.status = LcpStatus::numerical_failure;  // an empty root that no certificate confirms
      return r;
    }
    last = v.z;
    const RelativePairs rel = relative_pairs(problem, v.z);
    Index branch = -1;
    double worst = 0.0;
    for (Index i = 0; i < n; ++i) {
      const double both = std::min(rel.z(i), rel.w(i));
      if (fix[static_cast<std::size_t>(i)] == Fix::none && both > worst) {
        worst = both;
        branch = i;
      }
    }
    if (worst <= kComplementary) {
      if (std::optional<LcpResult> r =
              least_norm_pivoting(problem, v.z, options_.accuracy, kPolishRounds, nodes))
        return *r;
    }
    if (branch < 0) {  // complementary, but not to the accuracy: round-off at this node
      complete = false;
      continue;
    }
    // Children: the pair's larger member kept free, explored first (pushed last).
    std::vector<Fix> keep_z = fix;
    std::vector<Fix> keep_w = fix;
    keep_z[static_cast<std::size_t>(branch)] = Fix::w;
    keep_w[static_cast<std::size_t>(branch)] = Fix::z;
    const bool z_first = rel.z(branch) >= rel.w(branch);
    stack.push_back(z_first ? std::move(keep_w) : std::move(keep_z));
    stack.push_back(z_first ? std::move(keep_z) : std::move(keep_w));
  }
  // A proof needs every leaf proven empty: the simplex's verdict is checked by a certificate
  // of the leaf's own (its round-off can call a feasible node of a degenerate LCP empty).
  if (complete)
    complete =
        std::all_of(empty_leaves.begin(), empty_leaves.end(),
                    [&](const std::vector<Fix>& leaf) { return polyhedron.certified_empty(leaf); });
  const LcpStatus status = complete                     ? LcpStatus::no_solution
                           : work() > options_.max_work ? LcpStatus::iteration_limit
                                                        : LcpStatus::numerical_failure;
  return make_lcp_result(problem, status, last, nodes);
}

}  // namespace bimrock
