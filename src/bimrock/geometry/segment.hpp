#pragma once
/// @file Straight segments.
#include <algorithm>
#include <cmath>

#include <bimrock/geometry/vec2.hpp>

namespace bimrock {

struct Segment {
  Vec2 a;
  Vec2 b;

  [[nodiscard]] double length() const { return (b - a).norm(); }
  [[nodiscard]] Vec2 midpoint() const { return 0.5 * (a + b); }
  /// Unit direction from a to b.
  [[nodiscard]] Vec2 direction() const { return (b - a).normalized(); }
  /// Point at parameter t in [0, 1].
  [[nodiscard]] Vec2 at(double t) const { return a + t * (b - a); }
};

/// Distance from p to the infinite line through s.
inline double distance_to_line(const Segment& s, const Vec2& p) {
  return std::abs(cross(s.direction(), p - s.a));
}

/// Distance from p to the segment s.
inline double distance_to_segment(const Segment& s, const Vec2& p) {
  const Vec2 d = s.b - s.a;
  const double l2 = d.squaredNorm();
  if (l2 == 0.0)
    return (p - s.a).norm();
  const double t = std::clamp((p - s.a).dot(d) / l2, 0.0, 1.0);
  return (p - s.at(t)).norm();
}

}  // namespace bimrock
