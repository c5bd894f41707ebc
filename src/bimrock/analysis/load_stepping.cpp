#include <bimrock/analysis/load_stepping.hpp>

#include <algorithm>
#include <cmath>

namespace bimrock {
namespace {

/// Where a certificate bounds the collapse load, the trials go this far towards the bound (each
/// carried one shrinks the bracket tenfold) until one fails: the bound is often the collapse load
/// itself (its mechanism is the one that forms), where halving would take ~log2(gap /
/// tolerance) carried trials.
constexpr double kAimAtBound = 0.9;
/// At most this many kinks of softening laws inside one step.
constexpr int kMostKinks = 100;
/// Undecided trials once a failure is proven: then the bracket stands (see below).
constexpr int kUndecidedInBracket = 3;
/// Under displacement control, cuts of a failed step at most: a thousandth of the planned step
/// that still fails ends the stage (each cut costs a solve, and no load is bracketed).
constexpr int kMostDisplacementCuts = 10;
/// After a numerical failure, the parts carried grow by this factor each.
constexpr double kGrowth = 2.0;
/// Trials of one increment, carried or not, at most this many per bisection allowed.
constexpr int kTrialsPerBisection = 4;
/// Trials for a proof above the loads carried, where cutting ended without one: to the stage's
/// end, then each half as far, at most this many.
constexpr int kProofTrials = 4;

}  // namespace

SteppedIncrement step_increment(double step, double factor, const TryStep& try_step,
                                const CarryStep& carry, const SteppingOptions& options) {
  SteppedIncrement out;
  out.carried = factor;
  bool carried_any = false;
  const auto keep = [&](const Trial& t) {
    carry(t);
    out.carried = t.next.stage_factor;
    carried_any = true;
  };
  Trial t = try_step(step, Thoroughness::thorough);
  // A softening law that reaches its residual value inside the step: carry the step to there,
  // then the rest as a further step (the laws are linear on each side of the kink).
  double rest = step;
  for (int cuts = 0; cuts < kMostKinks && t.status == Trial::Status::carried && t.kink < 1.0;
       ++cuts) {
    const Trial to_kink = try_step(t.kink * rest, Thoroughness::thorough);
    if (to_kink.status != Trial::Status::carried)
      break;
    const double done = to_kink.next.stage_factor - out.carried;
    keep(to_kink);
    rest = options.displacement_control ? rest * (1.0 - t.kink) : rest - done;
    t = try_step(rest, Thoroughness::thorough);
  }
  if (t.status == Trial::Status::carried) {
    keep(t);
    return out;
  }
  // Bisect the failed step. The bracket's upper end is the nearest load proven to fail (a
  // certificate proves every step from a fraction of the failed one on).
  double remaining = rest;        // of this increment, in the units of `step`
  double failing_step = rest;     // from the state: proven to fail, or the last that failed
  std::optional<double> proven;   // stage factor of the nearest proof
  bool aim = false;               // aim at the certificate's bound
  bool retry = false;             // a numerical failure, then a carried part: try on
  bool growing = false;           // the rest, tried again, failed: the parts grow instead
  double part_carried = 0.0;      // the last part carried after a numerical failure
  int undecided = 0;              // trials neither carried nor proven to fail, once one was
  bool exhausted = false;         // the shortest failing step searched exhaustively
  int failing_rows = t.lcp_size;  // the LCP of the last step that failed undecided
  if (t.status == Trial::Status::collapse) {
    failing_step *= t.proven_fraction;
    proven = out.carried + failing_step;
    aim = t.proven_fraction < 1.0;
    out.failure = t;
  }
  // Proven to fail within the bracket tolerance of the first load, with nothing carried: unstable
  // under that load (bisecting towards zero load would only bracket round-off).
  const auto unstable_at_start = [&] {
    return options.first_load && !carried_any && proven && *proven <= options.bracket_tolerance;
  };
  // Each trial that fails is a bisection; parts carried are progress, and count against the
  // bisections only as a bound on the trials.
  int cuts = 0;
  int trials = 0;
  const int most_cuts = options.displacement_control
                            ? std::min(options.max_bisections, kMostDisplacementCuts)
                            : options.max_bisections;
  const auto go_on = [&] {
    return cuts < most_cuts && trials < kTrialsPerBisection * most_cuts && remaining > 0.0 &&
           !unstable_at_start();
  };
  for (; go_on(); ++trials) {
    // Under displacement control the step is a displacement and no load is bracketed: the
    // failed step is cut until a part carries, or the cuts run out.
    const double upper = proven ? *proven : out.carried + failing_step;
    const bool at_tolerance =
        !options.displacement_control &&
        std::abs(upper - out.carried) <= options.bracket_tolerance * std::abs(upper);
    // Cut to the tolerance without a proof: the shortest step that failed, undecided, is
    // searched once more, exhaustively (the whole search up to kExhaustiveRows rows, the root
    // LP alone up to kRootOnlyRows).
    if (at_tolerance &&
        (proven || exhausted || !(failing_step > 0.0) || failing_rows > kRootOnlyRows))
      break;
    // Nothing carried from a stage factor of 0, where the relative tolerance is never reached:
    // the same search once the step is below the tolerance of the stage's load (from rest with
    // no cohesion every cut asks the same LCP again), and the cuts go on where it decides
    // nothing.
    const bool search_at_start = !options.displacement_control && !proven && !exhausted &&
                                 !carried_any && out.carried == 0.0 && failing_step > 0.0 &&
                                 upper <= options.bracket_tolerance &&
                                 failing_rows <= kRootOnlyRows;
    const bool search = at_tolerance || search_at_start;
    if (search)
      exhausted = true;
    // After a numerical failure and a part carried, the rest is tried again whole; where that
    // fails too, the next parts grow from the last one instead (near a limit load the steps
    // that carry are small, and trying the whole rest before each costs a bisection or more).
    const bool retrying = retry;
    const double trial = search    ? failing_step
                         : !retry  ? (aim ? kAimAtBound : 0.5) * failing_step
                         : growing ? std::min(remaining, kGrowth * part_carried)
                                   : remaining;
    retry = false;
    // Inside a proven bracket a trial that stays undecided moves neither end: the pivoting
    // methods' search on a large LCP (seconds, where the active-set method takes milliseconds)
    // is left out there.
    const Thoroughness thoroughness = search   ? Thoroughness::exhaustive
                                      : proven ? Thoroughness::quick
                                               : Thoroughness::thorough;
    const Trial part = try_step(trial, thoroughness);
    if (part.status == Trial::Status::carried) {
      keep(part);
      remaining = trial == remaining ? 0.0 : remaining - trial;
      if (proven) {
        failing_step = *proven - out.carried;
      } else {
        failing_step -= trial;
        part_carried = trial;
        retry = true;
      }
    } else if (part.status == Trial::Status::collapse) {
      ++cuts;
      proven = out.carried + trial * part.proven_fraction;
      failing_step = *proven - out.carried;
      out.failure = part;
      aim = false;
    } else {
      ++cuts;
      failing_step = trial;
      failing_rows = part.lcp_size;
      aim = false;
      growing = growing || retrying;
      // Between a load carried and one proven to fail, each undecided trial costs a whole
      // search (the complete method, Lemke on the whole LCP, or the associated flow's proof of
      // a non-associated increment), and a part carried below it moves the bracket's lower end
      // by no more than the part: after a few, the bracket stands wider than the tolerance.
      if (proven && ++undecided >= kUndecidedInBracket) {
        out.undecided_inside = true;
        break;
      }
    }
  }
  // Cut to the tolerance without a proof (near a limit load of non-associated flow, between it
  // and the associated one, no increment may be solvable nor provably not): a proof may still
  // stand further up, where the load fails whatever the flow. The first trial goes to the
  // stage's end, each next one half as far: a shorter step's LCPs are smaller, and decided where
  // a long one's are left undecided. After a proof (its certificate may prove failure only near
  // the trial's end) the halving goes on while the trials prove and end below the nearest proof,
  // which bounds the collapse load.
  if (!proven && remaining > 0.0 && options.stage_end && *options.stage_end > out.carried) {
    double reach = *options.stage_end - out.carried;
    for (int k = 0; k < kProofTrials && reach > failing_step; ++k, reach /= 2.0) {
      const Trial far = try_step(reach, Thoroughness::proof);
      if (far.status == Trial::Status::collapse) {
        const double at = out.carried + reach * far.proven_fraction;
        if (!proven || at < *proven) {
          proven = at;
          out.failure = far;
        }
        out.undecided_inside = true;
        if (out.carried + reach / 2.0 >= *proven)
          break;  // the next trial would end past the proof
      } else if (proven) {
        break;
      }
    }
  }
  if (proven) {
    out.outcome = SteppedIncrement::Outcome::collapse;
    out.failed = *proven;
    out.unstable_at_first_load = unstable_at_start();
  } else if (remaining > 0.0) {
    out.outcome = SteppedIncrement::Outcome::undecided;
  }
  return out;
}

// The mechanism: the certificate of the failed step where it has one, else the flow of the last
// carried step (near collapse it is dominated by the mechanism).
Collapse describe_collapse(int stage, double carried, double failed, const Trial* failure,
                           const Trial* last) {
  Collapse c{stage, carried, failed, {}, {}};
  const Trial* source = failure && failure->ray.size() > 0 ? failure : last;
  if (!source || source->rows.empty())
    return c;
  const Eigen::VectorXd& flow = source == failure ? failure->ray : last->lambda;
  const double top = flow.cwiseAbs().maxCoeff();
  for (std::size_t k = 0; k < source->rows.size(); ++k) {
    const double l = flow(static_cast<Eigen::Index>(k));
    if (top > 0.0 && std::abs(l) > 1e-3 * top)
      c.mechanism.push_back({source->rows[k].point, source->rows[k].mode, l / top});
  }
  const double norm = source->du.norm();
  if (norm > 0.0)
    c.direction = source->du / norm;
  return c;
}

}  // namespace bimrock
