#include <bimrock/analysis/factor_of_safety_search.hpp>

#include <algorithm>
#include <optional>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/load_stepping.hpp>

namespace bimrock {

StrengthSelection selected_strengths(const Model& model, const FactorOfSafetyOptions& fos) {
  return fos.selection.joint_materials.empty() && fos.selection.block_materials.empty()
             ? all_strengths(model)
             : fos.selection;
}

FactorOfSafety find_factor_of_safety(const Model& model, const std::vector<YieldPoint>& points,
                                     const SpdSolver& k, const AnalysisState& start,
                                     const FactorOfSafetyOptions& fos,
                                     const PlasticOptions& options, const CandidateTuning& tuning,
                                     IncrementSolver& solver, IncrementMemory& memory,
                                     Timings& timings, const FactorTrialCallback& on_trial,
                                     const Presence* present) {
  const StrengthSelection selection = selected_strengths(model, fos);
  // The strength reduction is a stage of no load whose factor is F itself: the yield functions
  // of the reduced strengths are violated at the state carried, and each step's LCP finds the
  // plastic flow that restores them (eqs. 24-28 with dU_load = 0).
  Stage reduction;
  reduction.name = "factor of safety";
  const Eigen::VectorXd no_load = Eigen::VectorXd::Zero(model.n_dofs());
  AnalysisState state = start;
  state.stage_factor = 1.0;
  FactorOfSafety out;
  out.largest = fos.largest;
  const auto monitors = [&](const Eigen::VectorXd& u) {
    std::vector<Vec2> d;
    for (const Monitor& m : model.monitors)
      d.push_back(displacement_at(model, m.block, m.point, u) -
                  displacement_at(model, m.block, m.point, start.u));
    return d;
  };
  out.trials.push_back({1.0, 0.0, monitors(start.u)});
  std::optional<Trial> last;
  const TryStep try_step = [&](double step, Thoroughness thoroughness) {
    const Model reduced = reduce_strength(model, selection, state.stage_factor + step);
    const YieldEvaluator yield(reduced, points, present);
    const StageContext ctx{reduced, points, k, reduction, yield, no_load, {}, 0.0, &timings};
    return solve_increment(ctx, state, step, options, tuning, solver, memory, thoroughness);
  };
  const CarryStep carry = [&](const Trial& t) {
    state = t.next;
    out.lower = state.stage_factor;
    out.trials.push_back(
        {out.lower, t.lambda.size() > 0 ? t.lambda.cwiseAbs().maxCoeff() : 0.0, monitors(state.u)});
    last = t;
    if (on_trial)
      on_trial(out.trials.back());
  };
  const SteppingOptions stepping{fos.tolerance, options.max_bisections, false, false};
  while (state.stage_factor < fos.largest * (1.0 - 1e-12)) {
    const double step = std::min(fos.step, fos.largest - state.stage_factor);
    const SteppedIncrement done =
        step_increment(step, state.stage_factor, try_step, carry, stepping);
    if (done.outcome == SteppedIncrement::Outcome::collapse) {
      out.collapse =
          describe_collapse(0, done.carried, done.failed, done.failure ? &*done.failure : nullptr,
                            last ? &*last : nullptr);
      break;
    }
    if (done.outcome == SteppedIncrement::Outcome::undecided) {
      out.undecided = true;
      break;
    }
  }
  return out;
}

FactorOfSafety find_factor_below_one(const Model& model, const FactorOfSafetyOptions& fos,
                                     const Collapse& at_one, const RunStages& run,
                                     const FactorTrialCallback& on_trial) {
  FactorOfSafety out;
  out.largest = fos.largest;
  out.lower = 0.0;
  double upper = 1.0;
  Collapse failed = at_one;
  const double smallest = 1.0 / fos.largest;
  // One trial: true when the stages carry F (a trial kept, `lower` raised), false when they
  // collapse (`upper` lowered) or are undecided (the search ends).
  const auto carries = [&](double factor) {
    const StagesOutcome o = run(factor);
    if (o.undecided) {
      out.undecided = true;
      return false;
    }
    if (o.collapse) {
      upper = factor;
      failed = *o.collapse;
      return false;
    }
    out.lower = factor;
    std::vector<Vec2> monitors;
    for (const Monitor& m : model.monitors)
      monitors.push_back(displacement_at(model, m.block, m.point, o.state.u));
    out.trials.push_back({factor, o.largest_flow, monitors});
    if (on_trial)
      on_trial(out.trials.back());
    return true;
  };
  // Down in steps until a trial carries, then bisection of [lower, upper].
  bool bracketed = false;
  for (double f = 1.0 - fos.step; !out.undecided; f -= fos.step) {
    if (carries(std::max(f, smallest))) {
      bracketed = true;
      break;
    }
    if (f <= smallest)
      break;
  }
  while (bracketed && !out.undecided && upper - out.lower > fos.tolerance * upper)
    carries(0.5 * (out.lower + upper));
  std::sort(out.trials.begin(), out.trials.end(),
            [](const FactorTrial& a, const FactorTrial& b) { return a.factor < b.factor; });
  failed.carried = out.lower;
  failed.failed = upper;
  out.collapse = failed;
  return out;
}

}  // namespace bimrock
