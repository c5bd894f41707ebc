#include <bimrock/analysis/increment.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include <bimrock/analysis/associated_bound.hpp>
#include <bimrock/analysis/step_certificate.hpp>
#include <bimrock/assembly/yield_modes.hpp>  // kOpeningMode

namespace bimrock {
namespace {

/// Plastic displacements of a load-controlled step more than this many times its elastic ones
/// may be a mechanism resolved only by round-off (see flow_ratio()).
constexpr double kMechanismRatio = 1e6;

/// A mode of the LCP matrix whose stiffness, relative to the elastic one, is within this factor
/// of the accuracy of K's solves is taken for a mechanism (solve/solve_accuracy.hpp).
constexpr double kResolvableStiffness = 1e3;

// The elastic predictor: the increment if nothing yielded (eq. 24 with lambda = 0).
Eigen::VectorXd elastic_increment(const StageContext& ctx, double step) {
  return (ctx.controlled() ? step / ctx.control_rate : step) * ctx.x_ref;
}

// The largest violation of any yield function (unscaled, in Pa) and the points that violate them
// by more than tol; `all` gets every value.
std::vector<int> check_all_yield_functions(const StageContext& ctx, const AnalysisState& s,
                                           double tol, YieldValues& all) {
  ctx.yield.evaluate(s.points, s.u, all);
  std::vector<int> violators;
  for (std::size_t p = 0; p < ctx.points.size(); ++p)
    if (all.largest(p) > tol)
      violators.push_back(static_cast<int>(p));
  return violators;
}

// The plastic state after multipliers lambda (eqs. 29-35): an opening row's z is the total gap.
void update_state(const YieldSystem& sys, const Eigen::VectorXd& lambda, const Eigen::VectorXd& z,
                  const std::vector<YieldPoint>& points, AnalysisState& s) {
  for (int r = 0; r < sys.size(); ++r) {
    const YieldRow& row = sys.rows[r];
    PlasticState& ps = s.points[row.point];
    if (points[row.point].is_interface() && row.mode == kOpeningMode) {
      ps.plastic(0) += lambda(r);
      ps.gap = z(r);
      ps.max_gap = std::max(ps.max_gap, ps.gap);
    } else {
      ps.plastic += sys.flow[r] * lambda(r);
      ps.slip += lambda(r);
    }
  }
}

// The fraction of the step at which the first softening law of a joint reaches its residual
// value (its slope changes there, so a linear step must not run past it), or 1.
double first_kink(const Model& model, const std::vector<YieldPoint>& points,
                  const AnalysisState& before, const AnalysisState& after) {
  double fraction = 1.0;
  auto crossing = [&](double old_kappa, double new_kappa, const Softening& law) {
    const double d = law.distance;
    if (!std::isfinite(d) || law.peak == law.residual)
      return;
    const double margin = Softening::kKinkTolerance * std::max(d, 1e-300);
    if (old_kappa < d - margin && new_kappa > d + margin)
      fraction = std::min(fraction, (d - old_kappa) / (new_kappa - old_kappa));
  };
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (!points[p].is_interface())
      continue;
    const JointStrength& law = *model.joint_materials[points[p].material].strength;
    crossing(before.points[p].slip, after.points[p].slip, law.cohesion);
    crossing(before.points[p].slip, after.points[p].slip, law.friction);
    crossing(before.points[p].max_gap, after.points[p].max_gap, law.tensile);
  }
  return fraction;
}

// The (point, mode) rows a solve starts from after an LCP's multipliers z: the active ones and
// the joints whose gap changed (z is the total gap of an opening row).
std::set<std::pair<int, int>> active_rows(const YieldSystem& sys, const Eigen::VectorXd& z,
                                          const Eigen::VectorXd& gap_old) {
  std::set<std::pair<int, int>> rows;
  for (int r = 0; r < sys.size(); ++r)
    if (z(r) != gap_old(r) || z(r) > 0.0)
      rows.insert({sys.rows[r].point, sys.rows[r].mode});
  return rows;
}

// The warm start of the next round: the rows of z, and the modes of `violated` points whose yield
// function exceeds tol (a solve from z's rows would find just these violated, w = -f).
std::set<std::pair<int, int>> next_warm_rows(const YieldSystem& sys, const Eigen::VectorXd& z,
                                             const Eigen::VectorXd& gap_old,
                                             const std::vector<int>& violated, const YieldValues& f,
                                             double tol) {
  std::set<std::pair<int, int>> rows = active_rows(sys, z, gap_old);
  for (int p : violated) {
    const auto values = f.of(static_cast<std::size_t>(p));
    for (Eigen::Index k = 0; k < values.size(); ++k)
      if (values(k) > tol)
        rows.insert({p, static_cast<int>(k)});
  }
  return rows;
}

// The round's LCP (eqs. 24-28): nu = -f0 - C dU + N lambda with dU = dfactor x_ref + K^-1 Phi
// lambda; under displacement control dfactor = (step - h . lambda) / rate, h_r = control .
// K^-1 phi_r, keeps the monitor on its prescribed path. Warm: the rows in `warm_rows`, and the
// open joints.
IncrementLcp round_lcp(const StageContext& ctx, const YieldSystem& sys, const AnalysisState& s,
                       double step, const std::set<std::pair<int, int>>& warm_rows) {
  const bool control = ctx.controlled();
  const Eigen::VectorXd cx = sys.c * ctx.x_ref;
  const double load = control ? step / ctx.control_rate : step;
  IncrementLcp lcp{sys, ctx.points, -sys.f0 - cx * load, {}, {}, nullptr, {}, {}, nullptr, {}};
  if (control) {
    lcp.control = &ctx.control;
    lcp.control_term = cx / ctx.control_rate;
  } else {
    lcp.load_part = -cx * step;
  }
  const int m = sys.size();
  lcp.gap_old = Eigen::VectorXd::Zero(m);
  lcp.warm = Eigen::VectorXd::Zero(m);
  for (int r = 0; r < m; ++r) {
    const YieldRow& row = sys.rows[r];
    if (ctx.points[row.point].is_interface() && row.mode == kOpeningMode)
      lcp.gap_old(r) = s.points[row.point].gap;
    if (lcp.gap_old(r) > 0.0 || warm_rows.count({row.point, row.mode}))
      lcp.warm(r) = 1.0;
  }
  return lcp;
}

// On the reduced tangent, near a collapse, projected Newton can take many steps on a round's LCP
// that lacks the points of the mechanism: each iterate shown (SolverTuning::interrupt_after) is
// checked on every point, and points outside the LCP that it violates end the round at once (the
// next round holds them). A round on the points around the flow that stalls, shown twice as many
// iterates, ends too: past a collapse the larger LCP can leave projected Newton lowering its
// objective without end, where the smaller one's rounds find the mechanism's certificate.
struct IterateCheck {
  const StageContext& ctx;
  const AnalysisState& s;
  const YieldSystem& sys;
  const IncrementLcp& lcp;
  const Candidates& candidates;
  const IncrementSolver& solver;
  double step;
  double tol;
  int stall_after;
  std::vector<int> outside;  // points outside the LCP that the last iterate violates
  YieldValues f;             // every yield function at the last iterate
  int shown = 0;

  bool operator()(const LcpResult& iterate) {
    AnalysisState at = s;  // the tangent route runs under load control only
    const Eigen::VectorXd lambda = iterate.z - lcp.gap_old;
    at.u += step * ctx.x_ref + ctx.k.solve(Eigen::VectorXd(sys.phi * lambda));
    update_state(sys, lambda, iterate.z, ctx.points, at);
    outside.clear();
    const std::vector<int> in = candidates.in_lcp(solver);
    for (int p : check_all_yield_functions(ctx, at, tol, f))
      if (!std::binary_search(in.begin(), in.end(), p))
        outside.push_back(p);
    return !outside.empty() || (candidates.around() && ++shown > stall_after);
  }
};

// A mechanism that round-off turned into a very soft mode: with stiff (penalty) interfaces K^-1
// is accurate only to ~ penalty x machine precision, so the exact null direction of M (e.g. all
// blocks flowing plastically together) appears as a tiny positive eigenvalue and the multipliers
// blow up instead of a certificate being found. The step's plastic displacements over its
// elastic ones measure how soft the mode is (0 under displacement control, where the step
// prescribes the motion).
double flow_ratio(const StageContext& ctx, const AnalysisState& s,
                  const Eigen::VectorXd& plastic_du, double step) {
  if (ctx.controlled())
    return 0.0;
  // A step of no load (strength reduction) is measured against the displacements so far.
  const double elastic = std::abs(step) * ctx.x_ref.cwiseAbs().maxCoeff();
  const double scale = elastic > 0.0 ? elastic : s.u.cwiseAbs().maxCoeff();
  return scale > 0.0 ? plastic_du.cwiseAbs().maxCoeff() / scale : 0.0;
}

// Adds a solve's work to the trial's; whether it ran on the reduced tangent.
bool tally(const IncrementSolution& solution, Trial& t) {
  t.active_set_iterations += solution.active_set_iterations;
  t.tangent_factorizations += solution.tangent_factorizations;
  t.pivots += solution.pivots;
  return solution.on_tangent;
}

// A collapse with the mechanism's multipliers `ray` (none: no certificate), and its displacements
// unless the caller gave them.
Trial collapse(const YieldSystem& sys, const Eigen::VectorXd& ray, const StageContext& ctx,
               Trial t) {
  t.status = Trial::Status::collapse;
  t.rows = sys.rows;
  t.ray = ray;
  if (ray.size() > 0 && t.du.size() == 0)
    t.du = ctx.k.solve(Eigen::VectorXd(sys.phi * ray));
  return t;
}

// The elastic predictor's yield functions: f now, f at U + dU_elastic (f is linear in the stress
// for a given plastic state), and the tolerance of the checks (a fraction of the stress scale).
struct Prediction {
  YieldValues now;
  YieldValues predicted;
  double tol = 0.0;
};

Prediction predict(const StageContext& ctx, const AnalysisState& s, double step,
                   double yield_tolerance) {
  Prediction p;
  double scale = 0.0;
  ctx.yield.evaluate(s.points, s.u, p.now, &scale);
  ctx.yield.evaluate(s.points, Eigen::VectorXd(s.u + elastic_increment(ctx, step)), p.predicted,
                     &scale);
  p.tol = yield_tolerance * std::max(scale, 1.0);
  return p;
}

}  // namespace

Trial solve_increment(const StageContext& ctx, const AnalysisState& s, double step,
                      const PlasticOptions& options, const CandidateTuning& tuning,
                      IncrementSolver& solver, IncrementMemory& memory, Thoroughness thoroughness) {
  Trial t;
  LapTimer clock(ctx.timings);
  const Prediction p = predict(ctx, s, step, options.yield_tolerance);
  const double tol = p.tol;
  // Select the candidate rows, and warm-start from the rows that yielded in the last increment.
  Candidates candidates(ctx.model, ctx.points, s.points, p.now, p.predicted, tol, tuning,
                        memory.last_on_tangent ? &memory.last_active : nullptr);
  std::set<std::pair<int, int>> warm_rows = memory.last_active;
  clock.lap("increments: candidates");
  bool on_tangent = false;  // the last round's LCP ran on the reduced tangent
  for (t.rounds = 1; t.rounds <= options.max_rounds; ++t.rounds) {
    // The LCP holds every block the required points touch, and under displacement control the
    // monitor's.
    std::vector<char> blocks = candidates.required_blocks();
    if (std::find(blocks.begin(), blocks.end(), 1) != blocks.end()) {
      if (ctx.controlled())
        blocks[static_cast<std::size_t>(ctx.control_block)] = 1;
      solver.hold(blocks);
    }
    clock.lap("increments: condensation");
    const std::vector<int> lcp_points = candidates.in_lcp(solver);
    const YieldSystem sys = assemble_yield_system(ctx.model, ctx.points, s.points, s.u, lcp_points);
    clock.lap("increments: yield rows");
    t.lcp_size = sys.size();
    // Solve the increment's LCP.
    IncrementLcp lcp = round_lcp(ctx, sys, s, step, warm_rows);
    // Non-associated flow: the symmetric part of the splitting that finds the active set
    // (solve/symmetric_splitting.hpp), and the rows perturbed toward associated flow, assembled
    // only where the solver asks for them (IncrementLcp::perturbed). Under displacement control
    // the splitting's remainder holds the control term too.
    const bool non_associated = sys.size() > 0 && !follows_associated_flow(sys);
    std::optional<YieldSystem> along_flow;
    if (non_associated && solver.tuning().splitting) {
      along_flow = assemble_yield_system(ctx.model, ctx.points, s.points, s.u, lcp_points,
                                         FlowRule::gradient_along_flow);
      lcp.along_flow = &*along_flow;
      lcp.perturbed = [&ctx, &s, &lcp_points](double fraction) {
        return PerturbedRows{assemble_yield_system(ctx.model, ctx.points, s.points, s.u, lcp_points,
                                                   FlowRule::as_modelled, fraction),
                             assemble_yield_system(ctx.model, ctx.points, s.points, s.u, lcp_points,
                                                   FlowRule::gradient_along_flow, fraction)};
      };
    }
    Eigen::VectorXd z = lcp.gap_old;
    if (sys.size() > 0) {
      IterateCheck check{
          ctx, s, sys, lcp, candidates, solver, step, tol, solver.tuning().interrupt_after, {}, {}};
      const IncrementSolver::Interrupt interrupt = std::ref(check);
      using Outcome = IncrementSolution::Outcome;
      // Non-associated flow: no flow rule carries what associated flow cannot. Tried wherever
      // the solve did not end (the associated increment costs what a round of associated flow
      // does), before the pivoting methods and the next round: past the associated limit load
      // that proof is the answer, and what the pivoting methods find there (in seconds on a
      // large LCP) is a round that fails anyway.
      bool associated_tried = false;
      // A trial for a proof only, where the associated increment is solved without one: the
      // points outside the round's rows that its state violates. Its proof may need them: they
      // join a next round (as they would in an analysis with associated flow).
      std::vector<int> associated_outside;
      YieldValues associated_f;
      // The points outside the round's LCP (lcp_points, ascending) that a flow with
      // displacements `flow_du` violates (they keep their plastic state: only their
      // displacements change).
      const auto violated_outside = [&](const Eigen::VectorXd& flow_du, YieldValues& f) {
        AnalysisState at = s;
        at.u += step * ctx.x_ref + flow_du;
        std::vector<int> outside;
        for (int point : check_all_yield_functions(ctx, at, tol, f))
          if (!std::binary_search(lcp_points.begin(), lcp_points.end(), point))
            outside.push_back(point);
        return outside;
      };
      const auto associated_collapse = [&]() -> std::optional<Trial> {
        if (!non_associated || associated_tried)
          return std::nullopt;
        associated_tried = true;
        const bool for_proof = thoroughness == Thoroughness::proof;
        AssociatedBound bound = associated_bound(ctx, s, lcp_points, sys, lcp, solver, for_proof);
        tally(bound.associated, t);
        clock.lap("increments: LCP", "increments: K^-1 Phi columns",
                  bound.associated.columns_seconds);
        if (!bound.proven()) {
          if (for_proof && bound.flow_du.size() > 0)
            associated_outside = violated_outside(bound.flow_du, associated_f);
          return std::nullopt;
        }
        // The mechanism's displacements with the joints' own flow, K^-1 Phi r: with dilation
        // below friction the associated ones would show a joint opening that does not.
        t.proven_fraction = bound.proven_fraction;
        return collapse(sys, bound.ray, ctx, std::move(t));
      };
      const auto solve = [&](Routes routes) {
        const IncrementSolution solution =
            solver.solve(lcp, &interrupt, candidates.around(), thoroughness, routes);
        const bool tangent = tally(solution, t);
        if (routes != Routes::pivoting)
          on_tangent = tangent;
        clock.lap("increments: LCP", "increments: K^-1 Phi columns", solution.columns_seconds);
        return solution;
      };
      IncrementSolution solution = solve(non_associated ? Routes::up_to_pivoting : Routes::all);
      if (solution.pivoting_left) {
        if (std::optional<Trial> proven = associated_collapse())
          return std::move(*proven);
        solution = solve(Routes::pivoting);
      }
      if (solution.outcome == Outcome::interrupted) {
        if (std::optional<Trial> proven = associated_collapse())
          return std::move(*proven);
        // The next round holds the points the iterate violates, or goes on without the points
        // around the flow where it stalled on them.
        ++memory.interrupted_rounds;
        if (check.outside.empty()) {
          candidates.drop_around();
          ++memory.rounds_without_around;
        }
        candidates.require(check.outside, check.f, solver);
        warm_rows = next_warm_rows(sys, solution.z, lcp.gap_old, check.outside, check.f, tol);
        continue;
      }
      if (solution.outcome == Outcome::no_solution) {
        t.proven_fraction = solution.proven_fraction;
        return collapse(sys, solution.ray, ctx, std::move(t));
      }
      if (solution.outcome == Outcome::undecided) {
        if (std::optional<Trial> proven = associated_collapse())
          return std::move(*proven);
        if (!associated_outside.empty()) {
          candidates.require(associated_outside, associated_f, solver);
          continue;
        }
        // Associated flow: the round's LCP leaves the points outside it elastic, and past the
        // limit load it can still have solutions, of flows so large that no pivoting method
        // resolves them, which the points outside would have bounded (a mechanism held only by
        // their springs). Those that the last iterate's flow violates join a next round. (A
        // non-associated LCP is left undecided for more reasons, and its next rounds cost more
        // than they decide.)
        if (!non_associated && solution.z.size() == sys.size() && solution.z.allFinite()) {
          const Eigen::VectorXd flow_du =
              ctx.k.solve(Eigen::VectorXd(sys.phi * (solution.z - lcp.gap_old)));
          YieldValues f;
          if (candidates.require(violated_outside(flow_du, f), f, solver) > 0)
            continue;
        }
        return t;  // failed: the caller cuts the step
      }
      z = solution.z;
    }
    // Update: the displacements of the whole model (a solve with K's factor) and the plastic
    // state.
    const Eigen::VectorXd lambda = z - lcp.gap_old;
    const Eigen::VectorXd plastic_du = sys.size() > 0
                                           ? ctx.k.solve(Eigen::VectorXd(sys.phi * lambda))
                                           : Eigen::VectorXd::Zero(ctx.model.n_dofs());
    if (const double ratio = flow_ratio(ctx, s, plastic_du, step); ratio > kMechanismRatio) {
      // A mechanism where the flow certifies the LCP, or where the mode is too soft for K's
      // accuracy to tell from one: with penalty interfaces K's solves are accurate to 1e-8,
      // and modes 1e7 - 4e8 times softer than the elastic response are round-off's. Without
      // them (1e-16) a structure near its limit load can be as soft and still carry the step
      // (blocks on a short interface, restrained only by its springs, flow 1e6 - 2e7 times
      // their elastic motion): such a step is checked like any other.
      const Eigen::VectorXd r = lambda.cwiseMax(0.0);
      if (const double top = r.maxCoeff(); top > 0.0) {
        if (const std::optional<double> fraction =
                certified_step_fraction(ctx, sys, lcp, r / top)) {
          t.du = plastic_du / top;
          t.proven_fraction = *fraction;
          return collapse(sys, r / top, ctx, std::move(t));
        }
      }
      if (ratio * solver.k_accuracy() * kResolvableStiffness > 1.0) {
        const double top = lambda.cwiseAbs().maxCoeff();
        t.du = plastic_du / top;
        return collapse(sys, lambda.cwiseAbs() / top, ctx, std::move(t));
      }
    }
    const double dfactor =
        ctx.controlled() ? (step - ctx.control.dot(plastic_du)) / ctx.control_rate : step;
    t.du = dfactor * ctx.x_ref + plastic_du;
    t.next = s;
    t.next.u += t.du;
    t.next.stage_factor += dfactor;
    update_state(sys, lambda, z, ctx.points, t.next);
    // Check every yield function: the points violated outside the LCP join the next round.
    YieldValues f_next;
    const std::vector<int> violators = check_all_yield_functions(ctx, t.next, tol, f_next);
    clock.lap("increments: update and check");
    const std::size_t added = candidates.require(violators, f_next, solver);
    warm_rows = next_warm_rows(sys, z, lcp.gap_old, added > 0 ? violators : std::vector<int>{},
                               f_next, tol);
    if (added == 0) {
      memory.last_active = warm_rows;
      memory.last_on_tangent = on_tangent;
      t.rows = sys.rows;
      t.lambda = lambda;
      t.status = Trial::Status::carried;
      t.kink = first_kink(ctx.model, ctx.points, s, t.next);
      return t;
    }
  }
  return t;  // failed: no round without violated points
}

}  // namespace bimrock
