#include <bimrock/solve/active_set_lcp.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include <Eigen/Cholesky>
#include <Eigen/LU>

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

/// The shift and the steps of the inverse iteration that finds a singular block's kernel.
constexpr double kKernelShift = 1e-10;
constexpr int kInverseIterations = 4;

// A singular active block of a symmetric M may be the mechanism of a collapse: its kernel
// vector v, signed to be non-negative and extended by zeros, certifies that the LCP has no
// solution when also M v <= 0 off the active rows and q . v < 0 (Farkas, see lcp.hpp; for
// symmetric M, M^T v is the active columns times v). Returns the certificate or an empty vector.
Eigen::VectorXd kernel_certificate(const Eigen::MatrixXd& a, const Eigen::MatrixXd& m_rows,
                                   const Eigen::VectorXd& q,
                                   const std::vector<Eigen::Index>& rows) {
  const Eigen::Index k = a.rows();
  Eigen::VectorXd s(k);  // symmetric diagonal scaling: rows of M mix units
  for (Eigen::Index i = 0; i < k; ++i)
    s(i) = a(i, i) > 0.0 ? 1.0 / std::sqrt(a(i, i)) : 1.0;
  Eigen::MatrixXd shifted = s.asDiagonal() * (0.5 * (a + a.transpose())) * s.asDiagonal();
  // The eigenvector of the smallest eigenvalue by inverse iteration on the scaled block (unit
  // diagonal) shifted by 1e-10: one factorization, a small fraction of an eigendecomposition.
  // The start, all ones, is not orthogonal to a mechanism's multipliers (all >= 0).
  shifted.diagonal().array() += kKernelShift;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(shifted);
  if (ldlt.info() != Eigen::Success)
    return {};
  Eigen::VectorXd u = Eigen::VectorXd::Ones(k);
  for (int it = 0; it < kInverseIterations; ++it) {
    u = ldlt.solve(u);
    u /= u.norm();
  }
  if (!u.allFinite())
    return {};
  Eigen::VectorXd v = s.asDiagonal() * u;
  if (v.sum() < 0.0)
    v = -v;
  const double tiny = 1e-8 * v.cwiseAbs().maxCoeff();
  if (!(v.array() >= -tiny).all())
    return {};
  return certified_ray(q, rows, m_rows, v.cwiseMax(0.0));
}

// The active-set equations of an LCP given column by column: the columns of the active rows
// are asked for once each (kept for later iterations) and the active block is solved by a
// dense Cholesky (symmetric) or LU.
class ColumnEquations final : public ActiveSetEquations {
 public:
  ColumnEquations(LcpColumns& problem, double singular_tolerance)
      : problem_(problem),
        singular_tolerance_(singular_tolerance),
        slot_(static_cast<std::size_t>(problem.size()), -1),
        known_(problem.size(), 0) {}
  [[nodiscard]] Eigen::Index size() const override { return problem_.size(); }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return problem_.q(); }
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override { return problem_.group(row); }
  [[nodiscard]] int group_rank(Eigen::Index row) const override { return problem_.group_rank(row); }
  [[nodiscard]] bool symmetric() const override { return problem_.symmetric(); }

  using ActiveSetEquations::solve;
  // w is exact for the columns known, whatever the check asked for.
  Solution solve(const std::vector<Eigen::Index>& rows, const Damping& damping,
                 Check /*check*/) override {
    const Eigen::Index n = size();
    fetch(rows);
    const auto k = static_cast<Eigen::Index>(rows.size());
    Eigen::MatrixXd m_rows(n, k);  // the columns of M of the active rows
    for (Eigen::Index c = 0; c < k; ++c)
      m_rows.col(c) =
          known_.col(slot_[static_cast<std::size_t>(rows[static_cast<std::size_t>(c)])]);
    Eigen::MatrixXd a(k, k);
    Eigen::VectorXd rhs(k);
    for (Eigen::Index r = 0; r < k; ++r) {
      const Eigen::Index i = rows[static_cast<std::size_t>(r)];
      a.row(r) = m_rows.row(i);
      rhs(r) = -q()(i);
      if (damping.factor.size() > 0) {
        const double d = damping.factor(r) * a(r, r);
        a(r, r) += d;
        rhs(r) += d * damping.center(i);
      }
    }
    Solution out;
    out.z = Eigen::VectorXd::Zero(n);
    Eigen::VectorXd za = Eigen::VectorXd::Zero(k);
    if (k > 0) {
      // One step of iterative refinement after the solve.
      const auto refined = [&](const auto& factor) {
        Eigen::VectorXd x = factor.solve(rhs);
        x += factor.solve(rhs - a * x);
        return x;
      };
      // A symmetric block is positive semi-definite (the LCP is a convex program): Cholesky,
      // half the work of LU, unless it is singular.
      const Eigen::LLT<Eigen::MatrixXd> llt =
          problem_.symmetric() ? Eigen::LLT<Eigen::MatrixXd>(a) : Eigen::LLT<Eigen::MatrixXd>();
      if (problem_.symmetric() && llt.info() == Eigen::Success &&
          llt.rcond() > singular_tolerance_) {
        za = refined(llt);
      } else {
        const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
        if (!(lu.rcond() > singular_tolerance_)) {
          if (problem_.symmetric())
            out.ray = kernel_certificate(a, m_rows, q(), rows);
          return out;
        }
        za = refined(lu);
      }
      for (Eigen::Index r = 0; r < k; ++r)
        out.z(rows[static_cast<std::size_t>(r)]) = za(r);
    }
    out.w = m_rows * za + q();
    out.w_scale = m_rows.cwiseAbs() * za.cwiseAbs() + q().cwiseAbs();
    out.regular = true;
    return out;
  }

  // Any z: the columns of its support are asked for if not known yet.
  LcpResult result(LcpStatus status, Eigen::VectorXd z, int steps) override {
    std::vector<Eigen::Index> support;
    for (Eigen::Index i = 0; i < z.size(); ++i)
      if (z(i) != 0.0)
        support.push_back(i);
    fetch(support);
    LcpResult r;
    r.status = status;
    r.w = q();
    Eigen::VectorXd sizes = q().cwiseAbs();
    for (Eigen::Index i : support) {
      const auto column = known_.col(slot_[static_cast<std::size_t>(i)]);
      r.w += z(i) * column;
      sizes += std::abs(z(i)) * column.cwiseAbs();
    }
    r.residuals = measure(z, r.w, sizes);
    r.z = std::move(z);
    r.steps = steps;
    return r;
  }

 private:
  // Asks for the columns of `rows` not known yet: column slot_[i] of known_ is column i of M.
  void fetch(const std::vector<Eigen::Index>& rows) {
    std::vector<Eigen::Index> missing;
    for (Eigen::Index i : rows)
      if (slot_[static_cast<std::size_t>(i)] < 0)
        missing.push_back(i);
    if (missing.empty())
      return;
    const Eigen::MatrixXd fresh = problem_.columns(missing);
    const Eigen::Index first = known_.cols();
    known_.conservativeResize(size(), first + fresh.cols());
    known_.rightCols(fresh.cols()) = fresh;
    for (std::size_t k = 0; k < missing.size(); ++k)
      slot_[static_cast<std::size_t>(missing[k])] = first + static_cast<Eigen::Index>(k);
  }

  LcpColumns& problem_;
  double singular_tolerance_;
  std::vector<Eigen::Index> slot_;
  Eigen::MatrixXd known_;
};

// The objective of the quadratic program of a symmetric LCP, 1/2 z.M z + q.z, from w = M z + q.
// The multipliers z of a solve as an LCP iterate, where they have no negative entry: their w
// was measured by the solve (no back-solve).
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

}  // namespace

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
