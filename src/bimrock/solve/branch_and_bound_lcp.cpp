#include <bimrock/solve/branch_and_bound_lcp.hpp>

#include <algorithm>
#include <optional>
#include <vector>

#include <Eigen/QR>

#include <bimrock/solve/lcp_polyhedron.hpp>

namespace bimrock {
namespace {

using Index = Eigen::Index;
using Fix = LcpPolyhedron::Fix;

/// Pairs whose smaller member is below this (relative) count as complementary.
constexpr double kComplementary = 1e-10;

/// z_i and w_i relative to their scales: |z|_inf and the size of the terms that sum to w_i.
struct Relative {
  Eigen::VectorXd z;
  Eigen::VectorXd w;
};

Relative relative(const LcpProblem& p, const Eigen::VectorXd& z) {
  const Eigen::VectorXd w = p.m * z + p.q;
  const Eigen::VectorXd s = p.m.cwiseAbs() * z.cwiseAbs() + p.q.cwiseAbs();
  const double z_max = z.cwiseAbs().maxCoeff();
  Relative r{Eigen::VectorXd::Zero(p.size()), Eigen::VectorXd::Zero(p.size())};
  for (Index i = 0; i < p.size(); ++i) {
    r.z(i) = z_max > 0.0 ? z(i) / z_max : 0.0;
    r.w(i) = s(i) > 0.0 ? w(i) / s(i) : 0.0;
  }
  return r;
}

/// Rounds of the polish's active set: each moves the rows its last correction got wrong.
constexpr int kPolishRounds = 4;

/// The vertex made exact on its active rows A (z_i the larger of the pair): corrected twice by
/// the least-norm solution of M_AA dz_A = -(M z + q)_A (M_AA is singular where rows of one
/// yield point are dependent), which stays next to the vertex; else solved afresh from zero, or
/// the vertex itself: whichever first satisfies the LCP to the accuracy. Where none does, the
/// rows the correction violates join A and those it takes below zero leave, and A is tried
/// again. A vertex at a cohesionless apex has pairs with both z_i and w_i at zero to round-off
/// (its three yield functions vanish together), and the vertex alone cannot tell which of them
/// the solution needs active: an open joint point needs a slip row beside its opening row.
std::optional<LcpResult> polish(const LcpProblem& p, const Eigen::VectorXd& vertex,
                                const Relative& rel, double accuracy, int steps) {
  std::vector<char> in_a(static_cast<std::size_t>(p.size()));
  for (Index i = 0; i < p.size(); ++i)
    in_a[static_cast<std::size_t>(i)] = rel.z(i) > rel.w(i);
  Eigen::VectorXd corrected = vertex;
  for (int round = 0; round < kPolishRounds; ++round) {
    std::vector<Index> active;
    for (Index i = 0; i < p.size(); ++i)
      if (in_a[static_cast<std::size_t>(i)])
        active.push_back(i);
    Eigen::VectorXd fresh = Eigen::VectorXd::Zero(p.size());
    if (!active.empty()) {
      const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> m_aa(p.m(active, active));
      for (int k = 0; k < 2; ++k) {
        const Eigen::VectorXd w = p.m * corrected + p.q;
        const Eigen::VectorXd dz = m_aa.solve(Eigen::VectorXd(w(active)));
        corrected(active) -= dz;
      }
      const Eigen::VectorXd z_active = m_aa.solve(Eigen::VectorXd(-p.q(active)));
      fresh(active) = z_active;
    }
    for (Index i = 0; i < p.size(); ++i)
      if (!in_a[static_cast<std::size_t>(i)])
        corrected(i) = 0.0;
    for (const Eigen::VectorXd& candidate : {corrected, fresh, vertex}) {
      LcpResult r = make_lcp_result(p, LcpStatus::solved, candidate, steps);
      if (r.residuals.worst_relative() <= accuracy)
        return r;
    }
    const Relative now = relative(p, corrected);
    bool moved = false;
    for (Index i = 0; i < p.size(); ++i) {
      char& a = in_a[static_cast<std::size_t>(i)];
      if (a ? now.z(i) < -accuracy : now.w(i) < -accuracy) {
        a = !a;
        moved = true;
      }
    }
    if (!moved)
      break;
  }
  return std::nullopt;
}

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
  int nodes = 0;
  Eigen::VectorXd last = Eigen::VectorXd::Zero(n);
  while (!stack.empty()) {
    const double work = nodes * per_node + static_cast<double>(polyhedron.pivots()) * per_pivot;
    if (nodes >= options_.max_nodes || work > options_.max_work)
      return make_lcp_result(problem, LcpStatus::iteration_limit, last, nodes);
    const std::vector<Fix> fix = std::move(stack.back());
    stack.pop_back();
    const LcpPolyhedron::Vertex v = polyhedron.vertex(fix);
    ++nodes;
    if (v.status == LcpPolyhedron::Status::failed) {
      complete = false;
      continue;
    }
    if (v.status == LcpPolyhedron::Status::empty) {
      if (nodes > 1)
        continue;
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
    const Relative rel = relative(problem, v.z);
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
      if (std::optional<LcpResult> r = polish(problem, v.z, rel, options_.accuracy, nodes))
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
  return make_lcp_result(problem, complete ? LcpStatus::no_solution : LcpStatus::numerical_failure,
                         last, nodes);
}

}  // namespace bimrock
