#include <bimrock/analysis/limit_point.hpp>

#include <algorithm>
#include <cmath>

namespace bimrock {
namespace {

/// Increments on the plateau, at least, for a path that cannot be followed further to end at a
/// limit point (fewer: undecided).
constexpr int kLeastPlateau = 3;

}  // namespace

ControlPoint most_moved_block(const Model& model, const Eigen::VectorXd& du) {
  ControlPoint out;
  double most = 0.0;
  for (int b = 0; b < static_cast<int>(model.blocks.size()); ++b) {
    const Vec2 moved = du.segment<2>(6 * static_cast<Eigen::Index>(b));  // u0, v0 (eq. 1)
    if (moved.norm() > most) {
      most = moved.norm();
      out = {b, moved / most};
    }
  }
  return out;
}

LimitPoint follow_to_limit_point(double factor, const TryStep& try_controlled,
                                 const CarryStep& carry, const LimitPointOptions& options) {
  LimitPoint out;
  out.peak = factor;
  double current = factor;
  double moved = 0.0;         // by the controlled point, in the increments carried
  double plateau_from = 0.0;  // where the load factor last rose past the tolerance
  double tried = 0.0;         // the last step tried
  // A trial whose load would pass the stage's end is not carried, nor is anything after it:
  // its increment ends there as failed (load control takes over from the state before it).
  bool rises = false;
  const TryStep attempt = [&](double step, Thoroughness thoroughness) {
    if (rises)
      return Trial{};
    tried = step;
    Trial t = try_controlled(step, thoroughness);
    if (t.status == Trial::Status::carried && t.next.stage_factor > options.stage_end) {
      rises = true;
      return Trial{};
    }
    return t;
  };
  const CarryStep keep = [&](const Trial& t) {
    carry(t);
    current = t.next.stage_factor;
    moved += tried;
    out.last = t;
  };
  SteppingOptions stepping = options.stepping;
  stepping.displacement_control = true;
  stepping.stage_end.reset();
  const double tolerance = options.stepping.bracket_tolerance;
  int level = 0;  // increments carried in a row within the tolerance of the peak
  for (int n = 0; n < options.most_increments; ++n) {
    const SteppedIncrement done = step_increment(options.step, current, attempt, keep, stepping);
    if (rises) {
      out.outcome = LimitPoint::Outcome::rises;
      return out;
    }
    if (done.outcome != SteppedIncrement::Outcome::carried) {
      // The path ends here: at its peak where it has levelled off already (the plateau said,
      // with the parts of this increment that carried).
      if (level >= kLeastPlateau &&
          std::abs(current - out.peak) <= tolerance * std::abs(out.peak)) {
        out.outcome = LimitPoint::Outcome::limit_point;
        out.peak = std::max(out.peak, current);
        out.plateau = moved - plateau_from;
      }
      return out;
    }
    const double band = tolerance * std::abs(out.peak);
    if (current < out.peak - band) {
      out.outcome = LimitPoint::Outcome::limit_point;  // past the peak
      out.fell = true;
      return out;
    }
    if (current > out.peak + band) {
      plateau_from = moved;
      level = 0;
    } else {
      ++level;
    }
    out.peak = std::max(out.peak, current);
    out.plateau = moved - plateau_from;
    if (out.plateau >= options.plateau * (1.0 - 1e-12)) {
      out.outcome = LimitPoint::Outcome::limit_point;  // levelled off: a mechanism
      return out;
    }
  }
  return out;
}

}  // namespace bimrock
