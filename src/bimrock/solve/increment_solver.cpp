#include <bimrock/solve/increment_solver.hpp>

#include <algorithm>
#include <array>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include <bimrock/assembly/yield_modes.hpp>  // kOpeningMode
#include <bimrock/solve/fischer_burmeister_newton.hpp>
#include <bimrock/solve/lcp_polyhedron.hpp>
#include <bimrock/solve/least_norm_pivoting.hpp>
#include <bimrock/solve/solve_accuracy.hpp>
#include <bimrock/solve/symmetric_splitting.hpp>
#include <bimrock/solve/unsymmetric_tangent.hpp>
#include <bimrock/solve/working_set_lcp.hpp>

namespace bimrock {
namespace {

// The LCP in the unknowns of the zone, column by column: M = N - C S^-1 Phi (eq. 28) plus the
// displacement-control term, each column a solve with S (kept: FlexibilityColumns).
class LcpOnZone final : public LcpColumns {
 public:
  LcpOnZone(const YieldSystem& local, const std::vector<YieldPoint>& points, FlexibilityColumns& y,
            const Eigen::VectorXd& q, const Eigen::VectorXd& gap_old,
            const Eigen::VectorXd* control, Eigen::VectorXd control_term)
      : sys_(local),
        points_(points),
        y_(y),
        control_(control),
        control_term_(std::move(control_term)) {
    q_ = q;
    if (gap_old.size() > 0 && gap_old.cwiseAbs().maxCoeff() > 0.0)
      q_ -= times(gap_old);
  }
  // M v with one back-solve (no column of M formed).
  [[nodiscard]] Eigen::VectorXd times(const Eigen::VectorXd& v) {
    return times(v, y_.combine(sys_, v));
  }
  // (M - M_b) v for an LCP M_b of the same rows and the same flow Phi (the splitting's
  // remainder): the flow's displacement y = S^-1 Phi v is the same in both, one back-solve.
  [[nodiscard]] Eigen::VectorXd minus_times(const LcpOnZone& b, const Eigen::VectorXd& v) {
    const Eigen::VectorXd y = y_.combine(sys_, v);
    return times(v, y) - b.times(v, y);
  }
  [[nodiscard]] Eigen::Index size() const override { return sys_.size(); }
  // The modes of one yield point: at most 2 independent at a joint point (sigma_n, tau), 3 at a
  // block (its plane stress components).
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override {
    return sys_.rows[static_cast<std::size_t>(row)].point;
  }
  [[nodiscard]] int group_rank(Eigen::Index row) const override {
    const int point = sys_.rows[static_cast<std::size_t>(row)].point;
    return points_[static_cast<std::size_t>(point)].is_block() ? 3 : 2;
  }
  // Associated flow (C = Phi^T, N symmetric) under load control: M is symmetric (the control
  // term is not). Checked on first use only.
  [[nodiscard]] bool symmetric() const override {
    if (!symmetric_)
      symmetric_ = !control_ && follows_associated_flow(sys_);
    return *symmetric_;
  }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return q_; }
  [[nodiscard]] Eigen::MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    y_.prepare(sys_, cols);
    Eigen::MatrixXd out(size(), static_cast<Eigen::Index>(cols.size()));
    for (std::size_t k = 0; k < cols.size(); ++k) {
      const Eigen::VectorXd& y = y_.column(sys_, cols[k]);
      auto col = out.col(static_cast<Eigen::Index>(k));
      col = Eigen::VectorXd(sys_.n.col(cols[k])) - sys_.c * y;
      if (control_)
        col += control_term_ * control_->dot(y);
    }
    return out;
  }
  // The whole matrix, for Lemke (which needs every column).
  [[nodiscard]] LcpProblem dense() {
    std::vector<Eigen::Index> all(static_cast<std::size_t>(size()));
    for (Eigen::Index r = 0; r < size(); ++r)
      all[static_cast<std::size_t>(r)] = r;
    return {columns(all), q_};
  }
  // M in its sparse parts. Under displacement control M = N - C' S^-1 Phi with
  // C' = C - control_term control^T: the control couples every row to the monitor's few
  // unknowns.
  [[nodiscard]] SplitLcp split(const SparseMatrix& s_lower) {
    const SparseMatrix* c = &sys_.c;
    if (control_) {
      const SparseMatrix term = control_term_.sparseView();
      const SparseMatrix monitor = control_->sparseView();
      controlled_c_ = sys_.c - SparseMatrix(term * monitor.transpose());
      c = &controlled_c_;
    }
    SplitLcp split{&s_lower, c, &sys_.phi, &sys_.n, q_, {}, {}};
    for (Eigen::Index i = 0; i < size(); ++i) {
      split.group.push_back(group(i));
      split.group_rank.push_back(group_rank(i));
    }
    return split;
  }

 private:
  // M v given the flow's displacement y = S^-1 Phi v.
  [[nodiscard]] Eigen::VectorXd times(const Eigen::VectorXd& v, const Eigen::VectorXd& y) const {
    Eigen::VectorXd out = sys_.n * v - sys_.c * y;
    if (control_)
      out += control_term_ * control_->dot(y);
    return out;
  }

  const YieldSystem& sys_;
  const std::vector<YieldPoint>& points_;
  FlexibilityColumns& y_;
  const Eigen::VectorXd* control_;
  Eigen::VectorXd control_term_;
  Eigen::VectorXd q_;
  SparseMatrix controlled_c_;  // C' (split(), under displacement control)
  mutable std::optional<bool> symmetric_;
};

// The LCP of another's columns at a right-hand side of its own: the splitting's inner LCPs on
// the dense route, the rows along the flow at the right-hand side each iterate sets.
class AtRightHandSide final : public LcpColumns {
 public:
  explicit AtRightHandSide(LcpColumns& m) : m_(m) {}
  void set_q(const Eigen::VectorXd& q) { q_ = q; }
  [[nodiscard]] Eigen::Index size() const override { return m_.size(); }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return q_; }
  [[nodiscard]] Eigen::MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    return m_.columns(cols);
  }
  [[nodiscard]] bool symmetric() const override { return m_.symmetric(); }
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override { return m_.group(row); }
  [[nodiscard]] int group_rank(Eigen::Index row) const override { return m_.group_rank(row); }

 private:
  LcpColumns& m_;
  Eigen::VectorXd q_;
};

// The splitting's first iterate on the dense route: the LCP of the joints' opening rows alone
// (the tension cut-off, whose flow is its gradient: a symmetric block of M), solved; else
// `gap_old`. Each inner LCP freezes the friction term of the normal stresses of the last
// iterate, and a joint point predicted in tension has no shear strength there at all
// (|tau| <= -tan(phi) sigma < 0): the first inner LCP would have no solution. After the
// openings its normal stress is at most zero. (An opening row's multiplier is its total gap,
// as in the LCP itself.)
Eigen::VectorXd after_openings(LcpOnZone& on_zone, const YieldSystem& rows,
                               const std::vector<YieldPoint>& points,
                               const Eigen::VectorXd& gap_old, ActiveSetLcp& solver) {
  std::vector<Eigen::Index> opening;
  for (Eigen::Index i = 0; i < on_zone.size(); ++i) {
    const YieldRow& row = rows.rows[static_cast<std::size_t>(i)];
    if (points[static_cast<std::size_t>(row.point)].is_interface() && row.mode == kOpeningMode)
      opening.push_back(i);
  }
  if (opening.empty())
    return gap_old;
  const LcpProblem openings{on_zone.columns(opening)(opening, Eigen::indexing::all),
                            on_zone.q()(opening)};
  const LcpResult r = solver.solve(openings);
  if (r.status != LcpStatus::solved)
    return gap_old;
  Eigen::VectorXd start = Eigen::VectorXd::Zero(on_zone.size());
  start(opening) = r.z;
  return start;
}

// The splitting (symmetric_splitting.hpp) of a non-associated LCP on the reduced tangent:
// M = M~ + E, M~ the LCP of the rows along the flow (`symmetric_part`, with q = 0), solved by
// the symmetric route (Cholesky, the kept factor's updates) on `symmetric_tangent`, the
// equations of `symmetric_split`, whose q each inner LCP sets. The flow's columns S^-1 Phi are
// the same in both.
SplittingResult splitting_on_tangent(LcpOnZone& on_zone, LcpOnZone& symmetric_part,
                                     SplitLcp& symmetric_split,
                                     ReducedTangentEquations& symmetric_tangent,
                                     ActiveSetLcp& active_set, ActiveSetLcp& after_newton,
                                     const ActiveSetProposal& propose, const Eigen::VectorXd& start,
                                     const Eigen::VectorXd* warm, bool newton,
                                     IncrementSolution& out) {
  const SplittingRemainder remainder = [&](const Eigen::VectorXd& z) {
    return on_zone.minus_times(symmetric_part, z);
  };
  const SymmetricLcpSolve solve = [&](const Eigen::VectorXd& q, const Eigen::VectorXd* active,
                                      bool newton_step) {
    symmetric_split.q = q;
    LcpResult r =
        (newton_step ? after_newton : active_set).solve(symmetric_tangent, active, nullptr);
    out.active_set_iterations += r.steps;
    return r;
  };
  return solve_by_splitting(on_zone.q(), remainder, solve, propose, start, warm,
                            {.newton = newton});
}

// The same splitting on the dense route: the inner LCPs on the dense block of the rows along
// the flow (`symmetric_part`), each at the right-hand side its iterate sets.
SplittingResult splitting_on_dense(LcpOnZone& on_zone, LcpOnZone& symmetric_part,
                                   ActiveSetLcp& active_set, ActiveSetLcp& after_newton,
                                   const ActiveSetProposal& propose, const Eigen::VectorXd& start,
                                   const Eigen::VectorXd* warm, IncrementSolution& out) {
  AtRightHandSide inner(symmetric_part);
  const SplittingRemainder remainder = [&](const Eigen::VectorXd& z) {
    return on_zone.minus_times(symmetric_part, z);
  };
  const SymmetricLcpSolve solve = [&](const Eigen::VectorXd& q, const Eigen::VectorXd* active,
                                      bool newton_step) {
    inner.set_q(q);
    LcpResult r = (newton_step ? after_newton : active_set).solve(inner, active);
    out.active_set_iterations += r.steps;
    return r;
  };
  return solve_by_splitting(on_zone.q(), remainder, solve, propose, start, warm);
}

// The splitting's proposals, each tried by a step or two of the active-set method (`check`) on
// the LCP itself, given by `equations`; the first that solves it is kept in `solved`. Where
// one does not, its multipliers are the splitting's Newton step.
template <class Equations>
ActiveSetProposal proposals_on(Equations& equations, ActiveSetLcp& check, LcpResult& solved,
                               IncrementSolution& out) {
  return [&equations, &check, &solved, &out](const Eigen::VectorXd& active) {
    LcpResult tried = check.solve(equations, &active);
    out.active_set_iterations += tried.steps;
    if (tried.status != LcpStatus::solved)
      return ProposalOutcome{.solved = false, .z = std::move(tried.z)};
    solved = std::move(tried);
    return ProposalOutcome{.solved = true, .z = {}};
  };
}

/// Steps of the active-set method that try an active set the splitting proposes: one solves the
/// proposal's equations, one more lets a row or two that it missed settle.
constexpr int kProposalSteps = 2;

/// Steps of the active-set method on an inner LCP of the splitting after a Newton step, which is
/// taken back where they do not solve it (its remainder can ask more of the frozen strengths
/// than they have: an LCP without a solution, which the full budget would only confirm).
constexpr int kAfterNewtonSteps = 15;

/// Failed tries of the dense active block first in a row after which it is tried only on every
/// SolverTuning::dense_first_period-th LCP.
constexpr int kDenseFirstFailures = 3;

/// Rounds of least-norm pivoting that make the solution of the perturbed LCP one of the LCP
/// itself, and the accuracy it must reach (that of the active-set method's solutions).
constexpr int kLeastNormRounds = 10;
constexpr double kLeastNormAccuracy = 1e-9;

/// The perturbations of the flows (IncrementLcp::perturbed) whose solutions
/// IncrementSolver::from_perturbed() follows, largest first: from associated flow (t = 1, a
/// symmetric LCP, the easiest to solve) to the nearest to the LCP itself. (At dilation 0 and
/// friction phi, a small t is a dilation of about t tan(phi).)
constexpr std::array<double, 5> kFlowPerturbations{1.0, 1e-1, 1e-2, 1e-3, 1e-4};

/// The work of the linear program at an active set (IncrementSolver::from_perturbed), counted
/// as n^2 per simplex pivot on n rows: that of a branch and bound search (BranchAndBoundOptions),
/// and like it only on LCPs of at most its max_size rows. Measured on two random footings: on
/// 260 - 560 rows, 66 programs took 0.75 s in all, and gave the solutions that cut one analysis
/// from 70 s to 20 s; on 1 300 - 2 300 rows, 48 of 51 ran out of it, 0.3 - 0.5 s each.
constexpr double kPatternWork = 1e9;

/// The pairs of rows of one yield point that flow in exactly opposite directions (the slip rows
/// of a joint point at dilation 0): their columns of M cancel.
std::vector<std::pair<std::size_t, std::size_t>> opposite_flows(const YieldSystem& rows) {
  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  for (std::size_t i = 0; i + 1 < rows.rows.size(); ++i)
    for (std::size_t j = i + 1; j < rows.rows.size() && rows.rows[j].point == rows.rows[i].point;
         ++j)
      if ((rows.flow[i] + rows.flow[j]).squaredNorm() <= 1e-24 * rows.flow[i].squaredNorm())
        pairs.emplace_back(i, j);
  return pairs;
}

/// A solution `z` of the perturbed LCP read as one of the LCP itself: where both slips of a
/// pair that flow in exactly opposite directions are active, their common part becomes the
/// opening of the point. At a small perturbation t the two slips dilate by about t tan(phi)
/// each, and a point that opens does so with both active at multipliers of order 1 / t, whose
/// difference is the slip and whose sum times the dilation the opening: at t = 0 the same
/// motion needs the opening row. `pairs`: opposite_flows(rows). None where no point has both
/// slips of such a pair active.
std::optional<Eigen::VectorXd> opposite_slips_as_opening(
    const YieldSystem& rows, const std::vector<std::pair<std::size_t, std::size_t>>& pairs,
    const Eigen::VectorXd& z) {
  Eigen::VectorXd out = z;
  bool read = false;
  for (const auto& [i, j] : pairs) {
    const auto a = static_cast<Eigen::Index>(i);
    const auto b = static_cast<Eigen::Index>(j);
    const double both = std::min(out(a), out(b));
    if (!(both > 0.0))
      continue;
    for (std::size_t k = i; k < rows.rows.size() && rows.rows[k].point == rows.rows[i].point; ++k)
      if (rows.rows[k].mode == kOpeningMode) {
        const auto open = static_cast<Eigen::Index>(k);
        out(open) = std::max(out(open), both);
        out(a) -= both;
        out(b) -= both;
        read = true;
      }
  }
  if (!read)
    return std::nullopt;
  return out;
}

bool decided(const LcpResult& r) {
  return r.status == LcpStatus::solved || r.status == LcpStatus::no_solution;
}

}  // namespace

IncrementSolver::IncrementSolver(const Model& model, StiffnessFactor& k,
                                 const SparseMatrix& k_lower, const SolverTuning& tuning)
    : tuning_(tuning),
      k_(k.solver()),
      k_lower_(k_lower),
      zones_(model, k, k_lower, tuning.zones),
      active_set_(ActiveSetOptions{.max_iterations = tuning.active_set_iterations,
                                   .interrupt_after = tuning.interrupt_after}),
      proposal_check_(
          ActiveSetOptions{.max_iterations = kProposalSteps, .murty_after_cycle = false}),
      after_newton_(ActiveSetOptions{.max_iterations = kAfterNewtonSteps,
                                     .interrupt_after = tuning.interrupt_after}),
      dense_first_(kDenseFirstFailures, tuning.dense_first_period),
      exhaustive_(BranchAndBoundOptions{
          .max_nodes = static_cast<int>(kExhaustiveSearch * BranchAndBoundOptions{}.max_nodes),
          .max_work = kExhaustiveSearch * BranchAndBoundOptions{}.max_work}),
      root_only_(BranchAndBoundOptions{.max_nodes = 1,
                                       .max_root_work = 30.0 * BranchAndBoundOptions{}.max_work,
                                       .max_size = kRootOnlyRows}) {}

double IncrementSolver::k_accuracy() const {
  if (!k_accuracy_)
    k_accuracy_ = solve_accuracy(k_, k_lower_);
  return *k_accuracy_;
}

IncrementSolution IncrementSolver::solve(const IncrementLcp& lcp, const Interrupt* interrupt,
                                         bool stop_unsolved, Thoroughness thoroughness,
                                         Routes routes) {
  using Outcome = IncrementSolution::Outcome;
  IncrementSolution out;
  const CondensedStiffness& stiffness = zones_.stiffness();
  FlexibilityColumns& columns = zones_.columns();
  const double columns_before = columns.seconds();
  const YieldSystem local = stiffness.local(lcp.rows);
  const Eigen::VectorXd local_control =
      lcp.control ? stiffness.local(*lcp.control) : Eigen::VectorXd();
  LcpOnZone on_zone(local, lcp.points, columns, lcp.q, lcp.gap_old,
                    lcp.control ? &local_control : nullptr, lcp.control_term);
  const Eigen::Index m = on_zone.size();
  const Eigen::VectorXd* warm =
      lcp.warm.size() > 0 && lcp.warm.maxCoeff() > 0.0 ? &lcp.warm : nullptr;
  const auto finish = [&](Outcome outcome, const LcpResult& r) {
    out.outcome = outcome;
    if (outcome == Outcome::no_solution && r.ray.size() == m) {
      out.ray = r.ray;
      // Under load control q moves with the step and M does not: the ray proves every step
      // from some fraction of this one on (a tighter upper bound for the collapse bracket).
      if (lcp.load_part.size() == m)
        out.proven_fraction = certified_from(on_zone.q(), lcp.load_part, r.ray);
    } else if (outcome != Outcome::no_solution) {
      out.z = r.z;
    }
    out.columns_seconds = columns.seconds() - columns_before;
    return out;
  };
  LcpResult r;
  const bool thorough =
      thoroughness == Thoroughness::thorough || thoroughness == Thoroughness::exhaustive;
  const bool active_set = tuning_.active_set && routes != Routes::pivoting;
  const double expected_active = lcp.warm.sum();
  out.on_tangent = active_set && tuning_.reduced_tangent_rows >= 0 && !lcp.control &&
                   expected_active >= tuning_.reduced_tangent_rows;
  // A non-symmetric LCP with few rows active: the dense active block first. Where it
  // converges it costs a few LU factorizations of that block, where the splitting on the
  // reduced tangent solves tens of associated-form LCPs; where it does not, the tangent route
  // goes on.
  bool dense_tried = false;
  if (out.on_tangent && expected_active < tuning_.dense_first_rows && !on_zone.symmetric() &&
      dense_first_.try_now()) {
    r = active_set_.solve(on_zone, warm);
    out.active_set_iterations += r.steps;
    dense_tried = true;
    dense_first_.tried(decided(r));
    if (decided(r)) {
      out.on_tangent = false;
      return finish(r.status == LcpStatus::solved ? Outcome::solved : Outcome::no_solution, r);
    }
  }
  if (out.on_tangent) {
    // Many rows active: the equations of each active set on the sparse reduced tangent. It
    // reads no column of K^-1 Phi: those kept go, to make room for its factor.
    columns.clear();
    const SplitLcp split = on_zone.split(stiffness.lower());
    // Symmetric (associated flow): Cholesky, with the kept factor's updates; else LU, or GMRES
    // preconditioned by the tangent of the rows along the flow.
    std::optional<YieldSystem> along_flow;
    std::optional<LcpOnZone> symmetric_part;
    std::optional<SplitLcp> symmetric_split;
    std::optional<ReducedTangentEquations> symmetric_tangent;
    std::unique_ptr<ActiveSetEquations> equations;
    // The tangent's factorizations, the preconditioner's and the splitting's inner LCPs' among
    // them.
    const auto factorizations = [&] {
      return equations->factorizations() +
             (symmetric_tangent ? symmetric_tangent->factorizations() : 0);
    };
    Eigen::VectorXd proposed;  // non-associated flow: the splitting's last active set
    if (on_zone.symmetric()) {
      equations =
          std::make_unique<ReducedTangentEquations>(split, stiffness.factor(), zones_.tangent());
    } else {
      // The LCP of the rows along the flow, where it is symmetric (not for a softening law
      // whose coupling of the modes is not): its tangent preconditions the non-symmetric one,
      // and its equations, at the right-hand sides the splitting sets, are the inner LCPs.
      if (lcp.along_flow) {
        along_flow.emplace(stiffness.local(*lcp.along_flow));
        symmetric_part.emplace(*along_flow, lcp.points, columns, Eigen::VectorXd::Zero(m),
                               Eigen::VectorXd(), nullptr, Eigen::VectorXd());
        if (symmetric_part->symmetric()) {
          symmetric_split.emplace(symmetric_part->split(stiffness.lower()));
          symmetric_tangent.emplace(*symmetric_split, stiffness.factor(), zones_.tangent());
        }
      }
      UnsymmetricTangentEquations::Preconditioner preconditioner;
      if (symmetric_tangent && tuning_.iterative_tangent)
        preconditioner = [&](const std::vector<Eigen::Index>& active) {
          return symmetric_tangent->tangent_solve(active);
        };
      equations = std::make_unique<UnsymmetricTangentEquations>(split, stiffness.factor(),
                                                                std::move(preconditioner));
      if (symmetric_tangent && tuning_.splitting) {
        // The splitting proposes active sets, each tried on the LCP itself.
        const SplittingResult splitting = splitting_on_tangent(
            on_zone, *symmetric_part, *symmetric_split, *symmetric_tangent, active_set_,
            after_newton_, proposals_on(*equations, proposal_check_, r, out), lcp.gap_old, warm,
            tuning_.splitting_newton, out);
        out.tangent_factorizations += factorizations();
        if (splitting.solved)
          return finish(Outcome::solved, r);
        // Where no proposal solved it, the block rule seldom converges on a non-symmetric LCP
        // this large, and each of its steps costs a factorization: a quick solve ends here.
        if (!thorough)
          return finish(Outcome::undecided, r);
        if (splitting.proposals > 0) {
          proposed = (splitting.z.array() > 0.0).cast<double>();
          warm = &proposed;  // the block rule goes on from the last proposal's neighbourhood
        }
      }
    }
    const int factorizations_before = factorizations();
    r = active_set_.solve(*equations, warm, interrupt);
    out.active_set_iterations += r.steps;
    out.tangent_factorizations += factorizations() - factorizations_before;
    const bool unsolved = r.z.size() == m && (r.status == LcpStatus::iteration_limit ||
                                              r.status == LcpStatus::numerical_failure);
    if (r.status == LcpStatus::interrupted || (stop_unsolved && unsolved))
      return finish(Outcome::interrupted, r);
    const int dense_rows = thorough ? tuning_.dense_fallback_rows : tuning_.reduced_tangent_rows;
    if (!decided(r) && m > dense_rows)
      return finish(Outcome::undecided, r);  // too large for the dense routes
  }
  if (active_set && !decided(r) && !dense_tried) {
    r = active_set_.solve(on_zone, warm);
    out.active_set_iterations += r.steps;
  }
  if (active_set && !decided(r) && !out.on_tangent && !on_zone.symmetric() && lcp.along_flow &&
      tuning_.splitting) {
    // A non-symmetric LCP that the block rule did not solve on the dense active block: split,
    // as on the reduced tangent, its inner LCPs on the dense block of the rows along the flow
    // (projected Newton behind them). Lemke and branch and bound, which come next, end on rays
    // that prove nothing and search trees that outgrow their budget on the degenerate LCPs of
    // cohesionless joints with dilation below friction.
    const YieldSystem along_flow = stiffness.local(*lcp.along_flow);
    LcpOnZone symmetric_part(along_flow, lcp.points, columns, Eigen::VectorXd::Zero(m),
                             Eigen::VectorXd(), nullptr, Eigen::VectorXd());
    if (symmetric_part.symmetric() &&
        splitting_on_dense(on_zone, symmetric_part, active_set_, after_newton_,
                           proposals_on(on_zone, proposal_check_, r, out),
                           after_openings(on_zone, local, lcp.points, lcp.gap_old, active_set_),
                           warm, out)
            .solved)
      return finish(Outcome::solved, r);
  }
  if (!decided(r) && !thorough && m > tuning_.reduced_tangent_rows)
    return finish(Outcome::undecided, r);  // no pivoting on a large LCP
  if (!decided(r) && routes == Routes::up_to_pivoting) {
    out.pivoting_left = true;  // the caller's proof first
    return finish(Outcome::undecided, r);
  }
  // Under displacement control, where the semismooth Newton method below would start: the
  // active-set method's iterate (kept only there, Lemke replaces r).
  Eigen::VectorXd iterate;
  if (lcp.control)
    iterate = r.z.size() == m && r.z.allFinite() ? r.z : Eigen::VectorXd::Zero(m);
  if (tuning_.active_set && !decided(r)) {
    // Lemke on the rows that were violated or active (and those its solution violates): the
    // columns of the other rows are never formed.
    std::vector<Eigen::Index> initial;
    for (Eigen::Index i = 0; i < m; ++i)
      if ((warm && (*warm)(i) > 0.0) || (r.z.size() == m && r.z(i) > 0.0))
        initial.push_back(i);
    r = solve_on_working_set(on_zone, initial, lemke_);
    out.pivots += r.steps;
  }
  if (!decided(r)) {
    // Lemke on the whole matrix, then the complete method: Lemke decides an LCP only for
    // copositive-plus M, and on the degenerate LCPs of cohesionless joints and of
    // non-associated flow it can end on a ray that proves nothing. Branch and bound on the
    // pairs decides every LCP: a solution, or a proof that there is none.
    const LcpProblem dense = on_zone.dense();
    r = lemke_.solve(dense);
    out.pivots += r.steps;
    if (!decided(r) && tuning_.active_set && !follows_associated_flow(local)) {
      // The joints sticking: the openings alone, no slip, made exact by least-norm pivoting
      // (which lets the slip rows that state violates join). From rest on cohesionless joints
      // every point sits at its apex and the routes above fail on the degenerate LCP, where a
      // structure that stands often does so without slipping.
      const Eigen::VectorXd stick =
          after_openings(on_zone, local, lcp.points, lcp.gap_old, active_set_);
      if (std::optional<LcpResult> exact =
              least_norm_pivoting(dense, stick, kLeastNormAccuracy, kLeastNormRounds, r.steps))
        r = std::move(*exact);
    }
    if (!decided(r) && tuning_.active_set && lcp.perturbed && !opposite_flows(local).empty()) {
      if (std::optional<LcpResult> near = from_perturbed(lcp, dense, out))
        r = std::move(*near);
    }
    const bool exhaustive = thoroughness == Thoroughness::exhaustive;
    if (!decided(r) && (exhaustive || !(undecided_ && same_up_to_scale(*undecided_, dense)))) {
      r = !exhaustive            ? complete_.solve(dense)
          : m <= kExhaustiveRows ? exhaustive_.solve(dense)
                                 : root_only_.solve(dense);
      if (!decided(r))
        undecided_ = dense;
    }
  }
  if (tuning_.active_set && !decided(r) && lcp.control) {
    // Displacement control, where every method above has left the increment undecided (M is
    // not symmetric: no quadratic program, so no projected Newton behind the block rule). On
    // the equilibrium path the increment has a solution, and the semismooth Newton method,
    // whose merit falls at every step, goes on from the active-set method's iterate. It comes
    // last because where the others decide, they do it for less. Under load control it is not
    // tried: near a limit load the increments left undecided have no solution, where its merit
    // only levels off; what decides them is a proof.
    LcpResult newton =
        fischer_burmeister_newton(on_zone.split(stiffness.lower()), stiffness.factor(), iterate);
    out.active_set_iterations += newton.steps;
    out.tangent_factorizations += newton.steps;
    if (newton.status == LcpStatus::solved)
      r = std::move(newton);
  }
  if (r.status == LcpStatus::solved)
    return finish(Outcome::solved, r);
  return finish(r.status == LcpStatus::no_solution ? Outcome::no_solution : Outcome::undecided, r);
}

std::optional<LcpResult> IncrementSolver::from_perturbed(const IncrementLcp& lcp,
                                                         const LcpProblem& dense,
                                                         IncrementSolution& out) {
  Eigen::VectorXd warm = lcp.warm;
  bool any_solved = false;
  const std::vector<std::pair<std::size_t, std::size_t>> opposite = opposite_flows(lcp.rows);
  for (const double t : kFlowPerturbations) {
    const PerturbedRows rows = lcp.perturbed(t);
    const IncrementLcp near{rows.rows,   lcp.points,       lcp.q, lcp.load_part,    lcp.gap_old,
                            lcp.control, lcp.control_term, warm,  &rows.along_flow, {}};
    const IncrementSolution solved =
        solve(near, nullptr, false, Thoroughness::quick, Routes::up_to_pivoting);
    out.active_set_iterations += solved.active_set_iterations;
    out.tangent_factorizations += solved.tangent_factorizations;
    if (solved.outcome != IncrementSolution::Outcome::solved) {
      if (!any_solved)
        break;  // associated flow unsolved: past its limit load, none is solved
      continue;
    }
    any_solved = true;
    warm = (solved.z.array() > 0.0).cast<double>();
    if (std::optional<LcpResult> exact = least_norm_pivoting(
            dense, solved.z, kLeastNormAccuracy, kLeastNormRounds, solved.active_set_iterations))
      return exact;
    if (dense.size() > BranchAndBoundOptions{}.max_size)
      continue;  // the linear program below would run out of its budget (kPatternWork)
    // The active set that solution suggests, its opposite slips read as openings: the LCP's
    // solutions with it are the points z_A >= 0, M_AA z_A = -q_A, w_N >= 0 of one linear
    // program (M_AA singular at a cohesionless apex, where least-norm pivoting can only give
    // the least-norm one of them, with entries below zero).
    const std::optional<Eigen::VectorXd> read =
        opposite_slips_as_opening(lcp.rows, opposite, solved.z);
    if (!read)
      continue;
    std::vector<LcpPolyhedron::Fix> fix(static_cast<std::size_t>(dense.size()));
    for (Eigen::Index i = 0; i < dense.size(); ++i)
      fix[static_cast<std::size_t>(i)] =
          (*read)(i) > 0.0 ? LcpPolyhedron::Fix::w : LcpPolyhedron::Fix::z;
    const auto n = static_cast<double>(dense.size());
    LcpPolyhedron polyhedron(dense);
    const LcpPolyhedron::Vertex v =
        polyhedron.vertex(fix, static_cast<long>(kPatternWork / (n * n)) + 1);
    if (v.status == LcpPolyhedron::Status::feasible) {
      if (std::optional<LcpResult> exact = least_norm_pivoting(
              dense, v.z, kLeastNormAccuracy, kLeastNormRounds, solved.active_set_iterations))
        return exact;
    }
  }
  return std::nullopt;
}

}  // namespace bimrock
