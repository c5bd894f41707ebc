#include <bimrock/solve/active_set_lcp.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include <bimrock/solve/column_equations.hpp>
#include <bimrock/solve/projected_newton.hpp>

namespace bimrock {
namespace {

/// Relative size of a z_i or w_i of the wrong sign that is round-off (the accuracy asked of a
/// solution is 1e-9).
constexpr double kRoundOff = 1e-10;

// Keeps at most group_rank rows of each group active, those of highest priority: more would
// make the active block singular (three modes of a joint point in its two-dimensional stress
// space), which ends the method where a basic solution uses at most that many.
void limit_to_group_rank(const ActiveSetEquations& problem, const Eigen::VectorXd& priority,
                         std::vector<char>& active) {
  std::vector<std::pair<Eigen::Index, Eigen::Index>> members;  // (group, row) of active rows
  for (Eigen::Index i = 0; i < static_cast<Eigen::Index>(active.size()); ++i)
    if (active[static_cast<std::size_t>(i)])
      members.emplace_back(problem.group(i), i);
  std::sort(members.begin(), members.end());
  for (std::size_t a = 0; a < members.size();) {
    std::size_t b = a;
    while (b < members.size() && members[b].first == members[a].first)
      ++b;
    const auto rank = static_cast<std::size_t>(problem.group_rank(members[a].second));
    if (b - a > rank) {
      std::vector<Eigen::Index> rows;
      for (std::size_t k = a; k < b; ++k)
        rows.push_back(members[k].second);
      std::sort(rows.begin(), rows.end(), [&](Eigen::Index x, Eigen::Index y) {
        return priority(x) > priority(y) || (priority(x) == priority(y) && x < y);
      });
      for (std::size_t k = rank; k < rows.size(); ++k)
        active[static_cast<std::size_t>(rows[k])] = 0;
    }
    a = b;
  }
}

}  // namespace

using active_set::as_iterate;
using active_set::objective;
using active_set::projected_newton;

LcpResult ActiveSetLcp::solve(const LcpProblem& problem, const Eigen::VectorXd* warm_start) {
  check_lcp(problem);
  DenseLcpColumns columns(problem);
  return solve(columns, warm_start);
}

LcpResult ActiveSetLcp::solve(LcpColumns& problem, const Eigen::VectorXd* warm_start) {
  ColumnEquations equations(problem, options_.singular_tolerance);
  return solve(equations, warm_start);
}

LcpResult ActiveSetLcp::solve(ActiveSetEquations& problem, const Eigen::VectorXd* warm_start,
                              const Interrupt* interrupt) {
  const Eigen::Index n = problem.size();
  const Eigen::VectorXd& q = problem.q();
  if ((q.array() >= 0.0).all())
    return problem.result(LcpStatus::solved, Eigen::VectorXd::Zero(n), 0);
  if (warm_start != nullptr && warm_start->size() != n)
    throw std::invalid_argument("active-set LCP: warm start of the wrong size");

  std::vector<char> active(static_cast<std::size_t>(n));
  for (Eigen::Index i = 0; i < n; ++i)
    active[static_cast<std::size_t>(i)] = warm_start ? (*warm_start)(i) > 0.0 : q(i) < 0.0;
  {
    // Rows of the warm start first (above every -q_i), then the most violated.
    Eigen::VectorXd priority = -q;
    if (warm_start != nullptr)
      for (Eigen::Index i = 0; i < n; ++i)
        if ((*warm_start)(i) > 0.0)
          priority(i) += 2.0 * q.cwiseAbs().maxCoeff() + 1.0;
    limit_to_group_rank(problem, priority, active);
  }
  std::set<std::vector<char>> seen;  // an active set met twice is a cycle
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  auto result = [&](LcpStatus status, int iteration) {
    return problem.result(status, z, iteration);
  };
  // The last iterate, with multipliers that are negative only by round-off set to zero, if it
  // passes the check: degenerate rows (z_i ~ w_i ~ 0) can make the rules flip a row of a
  // solution back and forth.
  auto solved_or = [&](LcpStatus status, int iteration) {
    z = z.cwiseMax(0.0);
    LcpResult r = result(LcpStatus::solved, iteration);
    if (!r.z.allFinite() || !(r.residuals.worst_relative() <= options_.accuracy))
      r.status = status;
    return r;
  };
  // Near a degenerate solution (rows with z_i ~ w_i ~ 0) the block rule can cycle. Then it
  // switches to Murty's rule from the last iterate: change only the violated row of least index
  // (finite for P-matrices; here a safeguard, with its own cycle check).
  bool single = false;
  std::vector<char> last_active;  // the set of the last solve, and its w
  Eigen::VectorXd last_w;
  auto murty_step = [&]() {
    active = last_active;
    for (Eigen::Index i = 0; i < n; ++i) {
      const bool is_active = active[static_cast<std::size_t>(i)] != 0;
      if ((is_active && z(i) < 0.0) || (!is_active && last_w(i) < 0.0)) {
        active[static_cast<std::size_t>(i)] = is_active ? 0 : 1;
        break;
      }
    }
  };
  // Where the block rule does not converge, a symmetric problem goes on with projected Newton,
  // which cannot cycle. It starts from the block rule's iterate, projected on z >= 0, of least
  // objective (z = 0 has 0): near a limit load the last one can be far off (a nearly singular
  // block can give it huge negative multipliers).
  const bool newton = options_.projected_newton && problem.symmetric();
  LcpResult best = newton ? problem.result(LcpStatus::solved, Eigen::VectorXd::Zero(n), 0)
                          : LcpResult();  // measured: no back-solve for z = 0
  double best_objective = 0.0;
  bool best_measured = true;  // else best.z only, measured before projected Newton starts
  auto after_block_rule = [&](LcpStatus status, int iteration) {
    if (!newton)
      return solved_or(status, iteration);
    if (!best_measured)
      best = problem.result(LcpStatus::solved, best.z, iteration);
    return projected_newton(problem, options_, best, iteration, interrupt);
  };
  Eigen::Index fewest_violated = n + 1;  // the best count of violated rows so far
  int stalled = 0;                       // iterations since it was last lowered
  for (int iteration = 1; iteration <= 2 * options_.max_iterations; ++iteration) {
    if (!single && iteration > options_.max_iterations)
      break;
    if (!seen.insert(active).second) {
      if (newton)
        return after_block_rule(LcpStatus::iteration_limit, iteration);
      if (single || last_w.size() == 0 || !options_.murty_after_cycle)
        return solved_or(LcpStatus::iteration_limit, iteration);
      single = true;
      seen.clear();
      murty_step();
      if (!seen.insert(active).second)
        return solved_or(LcpStatus::iteration_limit, iteration);
    }
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < n; ++i)
      if (active[static_cast<std::size_t>(i)])
        rows.push_back(i);
    // The block rule needs only the signs of z and w: w from the solve's own equations (the
    // iterate that passes the rule is measured before it is taken).
    ActiveSetEquations::Solution step =
        problem.solve(rows, {}, ActiveSetEquations::Check::from_solve);
    if (!step.regular && step.ray.size() != n && newton)  // singular, not a mechanism
      return after_block_rule(LcpStatus::numerical_failure, iteration);
    if (!step.regular) {
      z.setZero();
      LcpResult failed = result(LcpStatus::numerical_failure, iteration);
      if (step.ray.size() == n) {
        failed.status = LcpStatus::no_solution;
        failed.ray = std::move(step.ray);
      }
      return failed;
    }
    z = std::move(step.z);
    const Eigen::VectorXd& w = step.w;
    if (newton) {
      // The iterate projected on z >= 0, a start for projected Newton. Where the step measured
      // w and z has no negative entry, it is z itself with its w (no back-solve).
      if (step.measured) {
        LcpResult projected = z.size() > 0 && z.minCoeff() >= 0.0
                                  ? as_iterate(z, step, iteration)
                                  : problem.result(LcpStatus::solved, z.cwiseMax(0.0), iteration);
        const double f = objective(projected.z, projected.w, q);
        if (f < best_objective) {
          best_objective = f;
          best = std::move(projected);
          best_measured = true;
        }
      } else {
        // An upper bound of the objective there, without a back-solve: with d = max(z, 0) - z,
        // f(z + d) = f(z) + w.d + d.M d / 2 and d.M d <= (sum |d_i| sqrt(M_ii))^2 for a positive
        // semi-definite M (|M_ij| <= sqrt(M_ii M_jj)). It ranks the starts only: the one chosen
        // is measured before projected Newton starts from it.
        const Eigen::VectorXd clipped = z.cwiseMax(0.0);
        double spread = 0.0;
        for (Eigen::Index i = 0; i < n; ++i)
          if (clipped(i) != z(i))
            spread += (clipped(i) - z(i)) * std::sqrt(problem.diagonal_bound(i));
        const double f = objective(z, w, q) + w.dot(clipped - z) + 0.5 * spread * spread;
        if (f < best_objective) {
          best_objective = f;
          best.z = clipped;
          best_measured = false;
        }
      }
    }
    // Rows that the rule would change only for round-off (z_i or w_i ~ 0, a degenerate
    // solution) can flip back and forth without a cycle the set check sees: an iterate that is a
    // solution to round-off is one, whatever the rule says.
    const double z_top = z.cwiseAbs().maxCoeff();
    Eigen::Index violated = 0;
    for (Eigen::Index i = 0; i < n; ++i)
      violated += active[static_cast<std::size_t>(i)] ? z(i) < -kRoundOff * z_top
                                                      : w(i) < -kRoundOff * step.w_scale(i);
    if (violated == 0) {
      const Eigen::VectorXd iterate = z;
      LcpResult r = solved_or(LcpStatus::numerical_failure, iteration);
      if (r.status == LcpStatus::solved)
        return r;
      if (!step.measured) {
        // The solve's own equations left it short of the accuracy (a sparse LU of a
        // non-symmetric tangent: ~1e-8): the same set, measured and refined.
        ActiveSetEquations::Solution exact = problem.solve(rows);
        if (exact.regular) {
          z = std::move(exact.z);
          r = solved_or(LcpStatus::numerical_failure, iteration);
          if (r.status == LcpStatus::solved)
            return r;
        }
      }
      z = iterate;
    }
    // Judice and Pires (1994): the block rule is trusted while it lowers the count of violated
    // rows; near a limit load it can swap tens of rows forever instead.
    stalled = violated < fewest_violated ? 0 : stalled + 1;
    fewest_violated = std::min(fewest_violated, violated);
    std::vector<char> next(static_cast<std::size_t>(n));
    for (Eigen::Index i = 0; i < n; ++i)
      next[static_cast<std::size_t>(i)] = z(i) > w(i);
    limit_to_group_rank(problem, z - w, next);
    bool changed = false;
    for (Eigen::Index i = 0; i < n; ++i)
      changed = changed || next[static_cast<std::size_t>(i)] != active[static_cast<std::size_t>(i)];
    last_active = active;
    last_w = w;
    if (newton && stalled >= options_.stall_iterations)
      return after_block_rule(LcpStatus::iteration_limit, iteration);
    if (single && changed)
      murty_step();
    else
      active = std::move(next);
    if (!changed)
      return after_block_rule(LcpStatus::numerical_failure, iteration);
  }
  return after_block_rule(LcpStatus::iteration_limit, options_.max_iterations);
}

}  // namespace bimrock
