#include <bimrock/solve/projected_newton.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace bimrock::active_set {

LcpResult as_iterate(const Eigen::VectorXd& z, const ActiveSetEquations::Solution& step,
                     int steps) {
  if (!step.measured)
    throw std::logic_error("active-set LCP: an iterate taken from a w not measured");
  LcpResult r;
  r.status = LcpStatus::solved;
  r.z = z;
  r.w = step.w;
  r.residuals = measure(z, step.w, step.w_scale);
  r.steps = steps;
  return r;
}

double objective(const Eigen::VectorXd& z, const Eigen::VectorXd& w, const Eigen::VectorXd& q) {
  return 0.5 * z.dot(w + q);
}

namespace {

/// Sufficient decrease (Armijo) of the projected line search, and its most halvings.
constexpr double kArmijo = 1e-4;
constexpr int kHalvings = 30;
/// Relative damping of the diagonal of a group left with more free rows than its rank
/// (keep_free_rows_within_group_rank), and the first of a whole singular block that is no
/// mechanism; the latter falls tenfold after each full step and ends below the smallest.
constexpr double kDamping = 1e-2;
constexpr double kSmallestDamping = 1e-6;

// Projected Newton's free rows `rows` (sorted, a group's consecutive) with at most as many rows
// of each group as its rank: its positive rows, then its rows at zero with w_i < 0, the most
// violated first. A row left out keeps z_i = 0 (d_i = 0): the direction still descends, and the
// block needs no damping for that group. With `settled` (the last step reached the Newton point
// of its free rows) every violated row of a group whose positive rows fill its rank joins too,
// damped: the solution may need it in place of one of them, which the limited steps cannot
// reach (on random grouped problems they stalled so). Damping the surplus rows of every group
// at every step instead would cut the steps short near a collapse, for more factorizations.
void keep_free_rows_within_group_rank(const ActiveSetEquations& problem, const Eigen::VectorXd& z,
                                      const Eigen::VectorXd& w, bool settled,
                                      std::vector<Eigen::Index>& rows) {
  std::vector<Eigen::Index> kept;
  kept.reserve(rows.size());
  std::vector<Eigen::Index> at_zero;
  for (std::size_t a = 0; a < rows.size();) {
    std::size_t b = a;
    while (b < rows.size() && problem.group(rows[b]) == problem.group(rows[a]))
      ++b;
    const auto rank = static_cast<std::size_t>(problem.group_rank(rows[a]));
    const std::size_t first = kept.size();
    at_zero.clear();
    for (std::size_t k = a; k < b; ++k)
      (z(rows[k]) > 0.0 ? kept : at_zero).push_back(rows[k]);
    const std::size_t positive = kept.size() - first;
    auto join = static_cast<std::ptrdiff_t>(at_zero.size());  // all: damped below if beyond rank
    if (b - a > rank && (positive < rank || !settled)) {
      join = static_cast<std::ptrdiff_t>(positive < rank ? rank - positive : 0);
      std::partial_sort(
          at_zero.begin(), at_zero.begin() + join, at_zero.end(),
          [&](Eigen::Index x, Eigen::Index y) { return w(x) < w(y) || (w(x) == w(y) && x < y); });
    }
    kept.insert(kept.end(), at_zero.begin(), at_zero.begin() + join);
    std::sort(kept.begin() + static_cast<std::ptrdiff_t>(first), kept.end());
    a = b;
  }
  rows = std::move(kept);
}

}  // namespace

// Projected Newton on the quadratic program of a symmetric LCP (Bertsekas 1982), the block rule
// made monotone: from z >= 0, the free rows F are those with z_i > 0 or w_i < 0; the Newton
// point solves M_FF z_F = -q_F (z = 0 elsewhere), and the step goes along the path
// max(0, z + t (z_N - z)), t = 1, 1/2, ..., to the first point that lowers the objective
// enough. The direction descends: on F it is -M_FF^-1 w_F, and the rows the projection clips
// have w_i < 0 and d_i < 0, which only steepens the path. So no active set comes back, where the
// block rule can swap tens of rows forever near a limit load. A group's rows join F only up to
// its rank, as a rule (keep_free_rows_within_group_rank); a group with more free rows than its
// rank, or a singular block that is no mechanism, is damped (a proximal step), which keeps the
// descent. `at` is the start, z >= 0 measured by problem.result().
LcpResult projected_newton(ActiveSetEquations& problem, const ActiveSetOptions& options,
                           LcpResult at, int iteration, const ActiveSetLcp::Interrupt* interrupt) {
  const Eigen::Index n = problem.size();
  const Eigen::VectorXd& q = problem.q();
  Eigen::VectorXd z = at.z;
  double f = objective(z, at.w, q);
  // Rows the last Newton point took below zero and the step left at zero stay out of the next
  // free set, although w_i < 0 there: else each Newton point asks for them to go negative again
  // and the clipped steps stall (Bertsekas's reason for his epsilon-active set).
  std::vector<char> held(static_cast<std::size_t>(n), 0);
  // The damping of every row once a block was singular and proved no collapse: kept (falling)
  // for the next steps, where each undamped try costs a failed factorization and a kernel search.
  double damp_all = 0.0;
  // The last step went the whole way to a Newton point with no negative multiplier.
  bool settled = false;
  // The caller's interrupt, if any, asked about the iterate `at` while it is not a solution.
  const auto interrupted = [&]() {
    return interrupt != nullptr && options.interrupt_after > 0 &&
           at.residuals.worst_relative() > options.accuracy && (*interrupt)(at);
  };
  for (int k = 0; k < options.max_iterations; ++k, ++iteration) {
    if (at.residuals.worst_relative() <= options.accuracy) {
      at.status = LcpStatus::solved;
      return at;
    }
    std::vector<Eigen::Index> rows;
    for (Eigen::Index i = 0; i < n; ++i)
      if (z(i) > 0.0 || (at.w(i) < 0.0 && !held[static_cast<std::size_t>(i)]))
        rows.push_back(i);
    keep_free_rows_within_group_rank(problem, z, at.w, settled, rows);
    // Damp the rows of the groups that still have more free rows than their rank (consecutive).
    ActiveSetEquations::Damping damping{
        Eigen::VectorXd::Zero(static_cast<Eigen::Index>(rows.size())), z};
    for (std::size_t a = 0; a < rows.size();) {
      std::size_t b = a;
      while (b < rows.size() && problem.group(rows[b]) == problem.group(rows[a]))
        ++b;
      if (b - a > static_cast<std::size_t>(problem.group_rank(rows[a])))
        damping.factor.segment(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b - a))
            .setConstant(kDamping);
      a = b;
    }
    damping.factor = damping.factor.cwiseMax(damp_all);
    ActiveSetEquations::Solution step = problem.solve(rows, damping);
    if (!step.regular && step.ray.size() == n) {
      LcpResult collapse =
          problem.result(LcpStatus::no_solution, Eigen::VectorXd::Zero(n), iteration);
      collapse.ray = std::move(step.ray);
      return collapse;
    }
    if (!step.regular && damp_all == 0.0) {
      damp_all = kDamping;
      damping.factor = damping.factor.cwiseMax(damp_all);
      step = problem.solve(rows, damping);
    }
    if (!step.regular) {
      at.status = LcpStatus::numerical_failure;
      return at;
    }
    const Eigen::VectorXd d = step.z - z;
    double taken = 0.0;  // the step length that lowered the objective enough (0: none)
    for (double t = 1.0; taken == 0.0 && t >= std::ldexp(1.0, -kHalvings); t *= 0.5) {
      // The full step is the Newton point itself, whose w the solve measured when it has no
      // negative multiplier.
      Eigen::VectorXd trial = (t == 1.0 ? step.z : Eigen::VectorXd(z + t * d)).cwiseMax(0.0);
      LcpResult next = t == 1.0 && step.z.minCoeff() >= 0.0
                           ? as_iterate(trial, step, iteration + 1)
                           : problem.result(LcpStatus::solved, trial, iteration + 1);
      const double f_next = objective(trial, next.w, q);
      // The Newton point itself is taken when it solves the LCP: near a solution the decrease
      // is round-off and would be refused.
      if (f_next <= f + kArmijo * at.w.dot(trial - z) ||
          (t == 1.0 && next.residuals.worst_relative() <= options.accuracy)) {
        taken = t;
        z = std::move(trial);
        at = std::move(next);
        f = f_next;
      }
    }
    for (Eigen::Index i = 0; i < n; ++i)
      held[static_cast<std::size_t>(i)] = step.z(i) < 0.0 && z(i) == 0.0;
    if (taken == 1.0)
      damp_all = damp_all * 0.1 < kSmallestDamping ? 0.0 : damp_all * 0.1;
    settled = taken == 1.0 && step.z.minCoeff() >= 0.0;
    if (taken == 0.0) {
      // No step lowers the objective: before failing, the caller may find that the iterate
      // violates rows the LCP lacks, and solve a larger one instead.
      at.status = interrupted() ? LcpStatus::interrupted : LcpStatus::numerical_failure;
      return at;
    }
    if (k + 1 >= options.interrupt_after && interrupted()) {
      at.status = LcpStatus::interrupted;
      return at;
    }
  }
  at.status = at.residuals.worst_relative() <= options.accuracy ? LcpStatus::solved
                                                                : LcpStatus::iteration_limit;
  return at;
}

}  // namespace bimrock::active_set
