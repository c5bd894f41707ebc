#include <bimrock/model/selector.hpp>

#include <algorithm>
#include <cmath>

namespace bimrock {

bool selects(const Selector& sel, const Segment& s, double tol) {
  switch (sel.kind) {
    case Selector::Kind::all:
      return true;
    case Selector::Kind::line:
      return distance_to_segment(sel.line, s.a) <= tol && distance_to_segment(sel.line, s.b) <= tol;
    case Selector::Kind::box:
      return sel.box.contains(s.a, tol) && sel.box.contains(s.b, tol);
    case Selector::Kind::orientation: {
      const Vec2 d = s.b - s.a;
      double angle = std::atan2(d.y(), d.x()) * 180.0 / M_PI;
      double diff = std::fmod(std::abs(angle - sel.angle_deg), 180.0);
      diff = std::min(diff, 180.0 - diff);
      return diff <= sel.angle_tolerance_deg;
    }
    case Selector::Kind::group:
      return std::any_of(sel.segments.begin(), sel.segments.end(), [&](const Segment& e) {
        return distance_to_segment(e, s.a) <= tol && distance_to_segment(e, s.b) <= tol;
      });
  }
  return false;
}

}  // namespace bimrock
