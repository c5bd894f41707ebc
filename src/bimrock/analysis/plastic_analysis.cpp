#include <bimrock/analysis/plastic_analysis.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <optional>
#include <string>
#include <utility>

#include <bimrock/analysis/excavation.hpp>
#include <bimrock/analysis/factor_of_safety_search.hpp>
#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/increment.hpp>
#include <bimrock/analysis/initial_state.hpp>
#include <bimrock/analysis/installation.hpp>
#include <bimrock/analysis/limit_point.hpp>
#include <bimrock/analysis/load_stepping.hpp>
#include <bimrock/analysis/stage_structure.hpp>
#include <bimrock/analysis/strength_reduction.hpp>
#include <bimrock/analysis/support_check.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/initial_forces.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/model/presence.hpp>
#include <bimrock/model/stage_blocks.hpp>
#include <bimrock/solve/factor_memory.hpp>

namespace bimrock {
namespace {

IncrementRecord record(const Model& model, const Trial& t, int stage, int increment,
                       double seconds) {
  IncrementRecord r;
  r.stage = stage;
  r.increment = increment;
  r.stage_factor = t.next.stage_factor;
  for (const Monitor& m : model.monitors)
    r.monitors.push_back(displacement_at(model, m.block, m.point, t.next.u));
  std::vector<char> yielded(t.next.points.size(), 0);
  for (std::size_t k = 0; k < t.rows.size(); ++k)
    if (std::abs(t.lambda(static_cast<Eigen::Index>(k))) > 0.0)
      yielded[t.rows[k].point] = 1;
  for (std::size_t p = 0; p < yielded.size(); ++p) {
    r.yielding_points += yielded[p];
    r.open_points += t.next.points[p].gap > 0.0 ? 1 : 0;
  }
  r.lcp_size = t.lcp_size;
  r.pivots = t.pivots;
  r.active_set_iterations = t.active_set_iterations;
  r.tangent_factorizations = t.tangent_factorizations;
  r.rounds = t.rounds;
  r.seconds = seconds;
  return r;
}

// Displacement control of `point` of `block` along `direction`: its row of K's unknowns and its
// rate along x_ref.
void control_point(StageContext& ctx, int block, const Vec2& point, const Vec2& direction) {
  ctx.control_block = block;
  ctx.control = Eigen::VectorXd::Zero(ctx.model.n_dofs());
  ctx.control.segment<6>(6 * static_cast<Eigen::Index>(block)) =
      block_Q(ctx.model.blocks[static_cast<std::size_t>(block)].centroid, point).transpose() *
      direction;
  ctx.control_rate = ctx.control.dot(ctx.x_ref);
}

// The stage's reference load: x_ref = K^-1 P_stage, and under displacement control the monitor's
// row of K's unknowns and its rate along x_ref.
StageContext stage_context(const Model& model, const std::vector<YieldPoint>& points,
                           const SpdSolver& k, const YieldEvaluator& yield, const Stage& stage,
                           const Eigen::VectorXd& load, Timings& timings) {
  StageContext ctx{model, points, k, stage, yield, {}, {}, 0.0, &timings};
  {
    ScopedTimer t(timings, "stage loads");
    ctx.x_ref = k.solve(load);
  }
  if (stage.control) {
    const Monitor& m = model.monitors[stage.control->monitor];
    control_point(ctx, m.block, m.point, stage.control->direction);
    if (!(std::abs(ctx.control_rate) > 0.0))
      throw ModelError("stage '" + stage.name + "': the controlled monitor '" + m.name +
                           "' does not move under the stage's loads",
                       {m.block});
  }
  return ctx;
}

// The stage's own loads on the blocks present; the first stage's less what the initial stress
// carries (its loads are in place from the start: it applies only the residual).
Eigen::VectorXd stage_loads(const Model& model, int stage, const std::vector<char>& present) {
  Eigen::VectorXd p = assemble_loads(model, model.stages[static_cast<std::size_t>(stage)].loads);
  if (stage == 0 && model.initial_stress)
    p -= initial_internal_forces(model);
  for (std::size_t b = 0; b < present.size(); ++b)
    if (!present[b])
      p.segment<6>(6 * static_cast<Eigen::Index>(b)).setZero();
  return p;
}

// Whether some material's dilation differs from its friction (the LCP is then not symmetric).
bool has_nonassociated_flow(const Model& model) {
  for (const JointMaterial& m : model.joint_materials)
    if (m.strength && (m.strength->dilation != m.strength->friction.peak ||
                       m.strength->dilation != m.strength->friction.residual))
      return true;
  for (const BlockMaterial& m : model.block_materials)
    if (m.strength && m.strength->dilation != m.strength->friction)
      return true;
  return false;
}

// A load-controlled stage left undecided goes on under displacement control of the centroid of
// the block that moved most in the last increment carried (`moved`), along its motion
// (analysis/limit_point.hpp). None where no block moved, or where the stage's load does not move
// that block elastically along its motion.
std::optional<StageContext> controlled_past_undecided(const StageContext& ctx,
                                                      const Eigen::VectorXd& moved) {
  const ControlPoint at = most_moved_block(ctx.model, moved);
  if (at.block < 0)
    return std::nullopt;
  StageContext controlled = ctx;
  control_point(controlled, at.block, ctx.model.blocks[static_cast<std::size_t>(at.block)].centroid,
                at.direction);
  const double motion = ctx.x_ref.segment<2>(6 * static_cast<Eigen::Index>(at.block)).norm();
  if (!(motion > 0.0 && controlled.control_rate > 1e-6 * motion))
    return std::nullopt;
  return controlled;
}

// Neither carried nor proven to fail: near a limit load the LCP is nearly singular, and with
// non-associated flow the splitting can fail to converge below it as well. The analysis stops,
// with every carried increment kept, and says what to try.
Stop undecided_stop(const Model& model, int stage_index, const Stage& stage, double carried,
                    bool searched) {
  std::string what_to_try =
      stage.control ? "; try more increments in this stage"
                    : "; to pass a limit load, prescribe a monitor's displacement in this stage "
                      "instead (stages[].control, docs/case-file.md)";
  if (searched)
    what_to_try += " (displacement control of the block that moved most found no limit point)";
  std::string why = "the structure is close to a limit load";
  if (has_nonassociated_flow(model)) {
    why += ", or with dilation below friction the increment is beyond the solver's reach";
    // Radenkovic's first theorem: no flow rule carries more than associated flow. Under load
    // control without softening the analysis runs that case itself (bound_by_associated_flow),
    // and the reason ends with what it found instead.
    if (stage.control && !has_softening(model))
      what_to_try +=
          "; with each dilation set equal to its friction (associated flow) the same "
          "case finds a collapse load that bounds this one's from above";
  }
  return Stop{stage_index, carried,
              "the increment after stage factor " + std::to_string(carried) +
                  " could not be solved accurately, nor shown to have no solution (" + why + ")" +
                  what_to_try};
}

// The result, with where the LCP phase's time went and what condensing cost.
PlasticResult with_statistics(PlasticResult result, const StageStructure& structure,
                              const IncrementMemory& memory) {
  const ZoneStatistics zones = structure.zone_statistics();
  result.timings.add("(LCP: tangent factorizations)", zones.tangent.factorize_seconds);
  result.timings.add("(LCP: tangent solves)", zones.tangent.solve_seconds);
  result.timings.add("(solves with K)", structure.solve_seconds());
  result.timings.add("(solves with S, K condensed)", zones.condensed.solve_seconds);
  result.stiffness_factorizations = structure.factorizations();
  result.condensations = zones.condensations;
  result.reserve_switches = zones.reserve_switches;
  result.regions = zones.regions;
  result.zone_blocks = zones.zone_blocks;
  result.tangent_factorizations = zones.tangent.factorizations;
  result.interrupted_rounds = memory.interrupted_rounds;
  result.rounds_without_around = memory.rounds_without_around;
  return result;
}

// Jacks the pretension `jack` of the bolts installed at stage `st`'s start against what stands
// (without them), as one load increment recorded in the stage as its increment 0, at stage factor
// 0 (its own loads not yet applied). False, with result.stopped saying why, if it cannot be
// carried.
bool carry_pretension(const Model& model, int st, StageStructure& structure,
                      const Eigen::VectorXd& jack, const PlasticOptions& options,
                      const CandidateTuning& tuning, IncrementMemory& memory,
                      const IncrementCallback& on_increment, PlasticResult& result) {
  Stage jacking;
  jacking.name = model.stages[static_cast<std::size_t>(st)].name + " (bolt pretension)";
  const YieldEvaluator yield(model, result.points, &structure.present());
  const StageContext ctx =
      stage_context(model, result.points, structure.k(), yield, jacking, jack, result.timings);
  result.state.stage_factor = 0.0;
  double jacked = 0.0;  // the fraction of the pretension carried
  auto part_start = std::chrono::steady_clock::now();
  const CarryStep carry = [&](const Trial& carried) {
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - part_start).count();
    jacked = carried.next.stage_factor;
    result.state = carried.next;
    result.state.stage_factor = 0.0;
    IncrementRecord r = record(model, carried, st, 0, secs);
    r.stage_factor = 0.0;
    result.history.push_back(std::move(r));
    if (on_increment)
      on_increment(result.history.back(), result.state);
    part_start = std::chrono::steady_clock::now();
  };
  const TryStep try_step = [&](double step, Thoroughness thoroughness) {
    AnalysisState from = result.state;
    from.stage_factor = jacked;
    return solve_increment(ctx, from, step, options, tuning, structure.solver(), memory,
                           thoroughness);
  };
  const SteppedIncrement done = step_increment(
      1.0, 0.0, try_step, carry, {options.bracket_tolerance, options.max_bisections, false, false});
  if (done.outcome == SteppedIncrement::Outcome::carried)
    return true;
  const std::string what = done.outcome == SteppedIncrement::Outcome::collapse
                               ? "the rock fails under " + std::to_string(done.failed) + " of it"
                               : "it could not be solved accurately beyond " +
                                     std::to_string(done.carried) + " of it, nor shown to fail";
  result.stopped = Stop{st, 0.0,
                        "the pretension of the bolts installed at the stage's start cannot be "
                        "jacked: " +
                            what + "; lower their pretension, or install them later"};
  return false;
}

// The stages of the model from the unloaded state, into `result` (its points given): every
// increment carried is recorded; the first collapse or undecided step ends them. `at_stage_end`
// (if any) is called with each stage carried. A stage that excavates stands on K of the blocks
// left and releases the forces of the blocks removed (analysis/excavation.hpp); a stage that
// installs blocks places them unstressed in the displaced structure and applies their weight over
// its increments; a stage that installs bolts first jacks their pretension against the structure
// without them, then locks them off and stands on K with them.
void run_stages(const Model& model, StageStructure& structure, const YieldPointIndex& index,
                const PlasticOptions& options, const PlasticTuning& plastic_tuning,
                IncrementMemory& memory, const IncrementCallback& on_increment,
                PlasticResult& result, const std::function<void(int)>& at_stage_end = {}) {
  const CandidateTuning& tuning = plastic_tuning.candidates;
  Eigen::VectorXd unbalanced;  // by the initial stress's points held to their strengths
  result.state = initial_state(model, result.points, unbalanced);
  structure.stand_on(presence_at(model, -1));
  Eigen::VectorXd unreleased = Eigen::VectorXd::Zero(model.n_dofs());
  for (int st = 0; st < static_cast<int>(model.stages.size()); ++st) {
    const Stage& stage = model.stages[st];
    const Presence before = structure.present();
    const Presence dug = before_bolts(model, before, st);
    if (dug != before) {
      unreleased +=
          excavation_forces(model, before, dug, result.state.u,
                            {&index, &result.state.points, &result.state.installed}, result.points);
      for (std::size_t p = 0; p < result.points.size(); ++p)
        if (!point_present(result.points[p], dug))
          result.state.points[p] = PlasticState{};  // gone with its blocks
      structure.stand_on(dug);
    }
    const Presence now = presence_at(model, st);
    const Eigen::VectorXd placed = install_blocks(model, index, st, now, result.state);
    if (now != dug) {
      const Eigen::VectorXd jack = pretension_loads(model, result.points, index, dug, now);
      if (!jack.isZero(0.0) && !carry_pretension(model, st, structure, jack, options, tuning,
                                                 memory, on_increment, result))
        return;
      lock_off(model, result.points, index, dug, now, result.state);
      structure.stand_on(now);
    }
    Eigen::VectorXd load = stage_loads(model, st, structure.present().blocks);
    if (st == 0)
      load += unbalanced;
    load += stage.release * unreleased + placed;
    unreleased *= 1.0 - stage.release;
    const YieldEvaluator yield(model, result.points, &structure.present());
    const StageContext ctx =
        stage_context(model, result.points, structure.k(), yield, stage, load, result.timings);
    const double step = (stage.control ? stage.control->displacement : 1.0) / stage.increments;
    result.state.stage_factor = 0.0;
    std::optional<Trial> last;  // the last carried trial of the stage
    int increment = 0;
    auto part_start = std::chrono::steady_clock::now();
    // Records a carried trial (a whole increment or a part of it) with the time since the last
    // part: the parts' times add up, none counts another's (nor the callback's).
    const CarryStep carry = [&](const Trial& carried) {
      const double secs =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - part_start).count();
      result.state = carried.next;
      result.history.push_back(record(model, carried, st, ++increment, secs));
      if (on_increment)
        on_increment(result.history.back(), result.state);
      last = carried;
      part_start = std::chrono::steady_clock::now();
    };
    const TryStep try_step = [&](double s, Thoroughness thoroughness) {
      return solve_increment(ctx, result.state, s, options, tuning, structure.solver(), memory,
                             thoroughness);
    };
    SteppingOptions stepping{options.bracket_tolerance, options.max_bisections,
                             stage.control.has_value(), false};
    if (!stage.control)
      stepping.stage_end = 1.0;
    const bool search_limit_point = !stage.control && plastic_tuning.limit_point_increments > 0;
    // Load control past a limit point's search whose load rose past the stage's end: the
    // increments left reach the stage's end exactly.
    bool off_grid = false;
    for (int n = 0; n < stage.increments; ++n) {
      SteppingOptions these = stepping;
      these.first_load = st == 0 && result.history.empty();
      part_start = std::chrono::steady_clock::now();
      const double this_step = off_grid ? std::min(step, 1.0 - result.state.stage_factor) : step;
      if (!(this_step > 0.0))
        break;
      const SteppedIncrement done =
          step_increment(this_step, result.state.stage_factor, try_step, carry, these);
      const std::optional<StageContext> controlled =
          done.outcome == SteppedIncrement::Outcome::undecided && search_limit_point
              ? controlled_past_undecided(ctx, last ? last->du : ctx.x_ref)
              : std::optional<StageContext>();
      if (controlled) {
        const TryStep controlled_step = [&](double s, Thoroughness thoroughness) {
          return solve_increment(*controlled, result.state, s, options, tuning, structure.solver(),
                                 memory, thoroughness);
        };
        // Steps of a tenth of the point's elastic motion under the stage's whole load (one
        // increment's, where the stage has more), and a plateau as long as that motion: the
        // point's motion on it is then at least half plastic.
        const double elastic = controlled->control_rate;
        const LimitPoint past =
            follow_to_limit_point(result.state.stage_factor, controlled_step, carry,
                                  {.step = elastic / std::max(stage.increments, 10),
                                   .stepping = stepping,
                                   .plateau = elastic,
                                   .most_increments = plastic_tuning.limit_point_increments});
        if (past.outcome == LimitPoint::Outcome::rises) {
          off_grid = true;
          continue;
        }
        if (past.outcome == LimitPoint::Outcome::limit_point) {
          if (these.first_load && past.peak <= options.bracket_tolerance) {
            // Nothing carried, and the load factor level at zero from the start: near zero
            // load joints without cohesion or tensile strength have next to no strength, so a
            // prescribed motion meets no resistance whether or not the structure carries its
            // load. Only load control's proof says "unstable under the first load".
            result.stopped = undecided_stop(model, st, stage, result.state.stage_factor, false);
            result.stopped->reason +=
                " (displacement control of the block that moved most found the load factor "
                "level at zero from the start, which proves no collapse: near zero load, joints "
                "without cohesion or tensile strength have next to no strength)";
            return;
          }
          result.collapse = describe_collapse(st, past.peak, past.peak, nullptr, &*past.last);
          Collapse& c = *result.collapse;
          c.limit_point = true;
          c.control_block = controlled->control_block;
          c.plateau = past.plateau;
          c.fell = past.fell;
          c.elastic = elastic;
          return;
        }
      }
      if (done.outcome == SteppedIncrement::Outcome::undecided) {
        result.stopped =
            undecided_stop(model, st, stage, result.state.stage_factor, search_limit_point);
        return;
      }
      if (done.outcome == SteppedIncrement::Outcome::collapse) {
        result.collapse =
            describe_collapse(st, done.carried, done.failed,
                              done.failure ? &*done.failure : nullptr, last ? &*last : nullptr);
        result.collapse->unstable_at_first_load = done.unstable_at_first_load;
        result.collapse->undecided_inside = done.undecided_inside;
        return;
      }
    }
    if (at_stage_end)
      at_stage_end(st);
  }
}

// F < 1, for stages that collapse up to `fos_stage` (result.collapse): each trial runs them
// again from the start with the strengths raised.
FactorOfSafety factor_below_one(const Model& model, int fos_stage, StageStructure& structure,
                                const YieldPointIndex& index, const PlasticOptions& options,
                                const PlasticTuning& tuning, IncrementMemory& memory,
                                PlasticResult& result, const FactorTrialCallback& on_trial) {
  Model until = model;
  until.stages.resize(static_cast<std::size_t>(fos_stage) + 1);
  const StrengthSelection selection = selected_strengths(model, *options.factor_of_safety);
  const RunStages run = [&](double factor) {
    const Model stronger = reduce_strength(until, selection, factor);
    PlasticResult trial;
    trial.points = result.points;
    run_stages(stronger, structure, index, options, tuning, memory, {}, trial);
    for (const auto& [phase, seconds] : trial.timings.phases)
      result.timings.add(phase, seconds);
    StagesOutcome o{trial.state, 0.0, trial.collapse, trial.stopped.has_value()};
    for (const PlasticState& p : trial.state.points)
      o.largest_flow = std::max(o.largest_flow, p.slip);
    return o;
  };
  FactorOfSafety f =
      find_factor_below_one(model, *options.factor_of_safety, *result.collapse, run, on_trial);
  f.stage = fos_stage;
  return f;
}

// What associated flow did where it gives no bound of the stop's load (bound_by_associated_flow):
// its collapse (`bound`) or its stop (`stopped`), if any, beside the original model's `stop`.
std::string why_no_bound(const Stop& stop, const std::optional<Collapse>& bound,
                         const std::optional<Stop>& stopped) {
  if (bound && bound->stage == stop.stage)
    return bound->limit_point
               ? "; associated flow reaches only a limit point in this stage, not a proof"
               : "; associated flow collapses below the load carried here, which no flow rule "
                 "allows: round-off";
  if (stopped)
    return stopped->stage == stop.stage ? "; associated flow stops undecided in this stage too"
                                        : "; associated flow stops undecided in an earlier stage";
  return bound ? "; associated flow collapses in an earlier stage"
               : "; associated flow carries this stage, so bounds nothing";
}

// A stop under load control in a model whose flow is not associated and whose strengths do not
// soften: the same stages, up to the one that stopped, with associated flow. Where they collapse
// in that stage (a proof, not a limit point), their collapse load bounds this model's from
// above (strength_reduction.hpp, with_associated_flow), and the stop becomes a collapse
// bracketed by the load carried and that bound. Otherwise the stop stands, and its reason says
// what associated flow did.
void bound_by_associated_flow(const Model& model, const YieldPointIndex& index,
                              const PlasticOptions& options, const PlasticTuning& tuning,
                              PlasticResult& result) {
  const Stop stop = *result.stopped;
  if (model.stages[static_cast<std::size_t>(stop.stage)].control ||
      !has_nonassociated_flow(model) || has_softening(model))
    return;
  Model associated = with_associated_flow(model);
  associated.stages.resize(static_cast<std::size_t>(stop.stage) + 1);
  PlasticResult trial;
  trial.points = result.points;
  {
    ScopedTimer t(result.timings, "(associated flow's bound)");
    // A solver of its own: what the stopped run's solver remembers (LCPs left undecided, the
    // routes that failed) is of the other flow rule.
    StageStructure structure(associated, tuning.solver, tuning.stiffness, trial.timings);
    IncrementMemory memory;
    run_stages(associated, structure, index, options, tuning, memory, {}, trial);
  }
  for (const auto& [phase, seconds] : trial.timings.phases)
    result.timings.add(phase, seconds);
  const std::optional<Collapse>& bound = trial.collapse;
  // By the static theorem the original model cannot carry more than associated flow: a bound
  // below the load carried (beyond the bracket tolerance) would be round-off's, and is not used.
  const bool bounds = bound && bound->stage == stop.stage && !bound->limit_point &&
                      bound->failed >= stop.factor * (1.0 - options.bracket_tolerance);
  if (!bounds) {
    result.stopped->reason += why_no_bound(stop, bound, trial.stopped);
    return;
  }
  Collapse c = *bound;
  c.carried = stop.factor;
  c.failed = std::max(bound->failed, stop.factor);
  c.undecided_inside = c.failed - c.carried > options.bracket_tolerance * c.failed;
  c.associated_bound = true;
  c.unstable_at_first_load = bound->unstable_at_first_load && stop.factor == 0.0;
  result.collapse = std::move(c);
  result.stopped.reset();
}

}  // namespace

PlasticResult run_plastic_analysis(const Model& model, const PlasticOptions& options,
                                   const IncrementCallback& on_increment,
                                   const PlasticTuning& tuning,
                                   const FactorTrialCallback& on_factor_trial) {
  const KeptFactorMemoryRelease release_at_end;  // declared first: runs after the factors go
  PlasticResult result;
  {
    ScopedTimer t(result.timings, "check supports");
    check_supports(model);
  }
  YieldPointIndex index;
  result.points = make_yield_points(model, &index);
  if (model.initial_stress && !model.stages.empty())
    result.initial_stress = check_initial_stress(model, result.points, options);
  // K of the blocks present, assembled and factorized by run_stages at the start and again only
  // after a stage that excavates (its lower triangle is kept: the reduced tangent is K minus the
  // plastic part).
  StageStructure structure(model, tuning.solver, tuning.stiffness, result.timings);
  IncrementMemory memory;
  if (!options.factor_of_safety) {
    run_stages(model, structure, index, options, tuning, memory, on_increment, result);
    if (result.stopped)
      bound_by_associated_flow(model, index, options, tuning, result);
    return with_statistics(std::move(result), structure, memory);
  }
  // The factor of safety after its stage (by default the last), from the state reached there;
  // it is a part of the phases' times too: its own phase says what F costs over the stages.
  const FactorOfSafetyOptions& fos = *options.factor_of_safety;
  const int fos_stage = fos.after_stage.value_or(static_cast<int>(model.stages.size()) - 1);
  const auto factor_of_safety_after = [&](int stage) {
    if (stage != fos_stage)
      return;
    ScopedTimer t(result.timings, "(factor of safety)");
    result.factor_of_safety = find_factor_of_safety(
        model, result.points, structure.k(), result.state, fos, options, tuning.candidates,
        structure.solver(), memory, result.timings, on_factor_trial, &structure.present());
    result.factor_of_safety->stage = fos_stage;
  };
  run_stages(model, structure, index, options, tuning, memory, on_increment, result,
             factor_of_safety_after);
  if (result.stopped)
    bound_by_associated_flow(model, index, options, tuning, result);
  if (result.collapse && result.collapse->stage <= fos_stage) {
    ScopedTimer t(result.timings, "(factor of safety)");
    result.factor_of_safety = factor_below_one(model, fos_stage, structure, index, options, tuning,
                                               memory, result, on_factor_trial);
  }
  return with_statistics(std::move(result), structure, memory);
}

}  // namespace bimrock
