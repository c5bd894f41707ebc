#pragma once
/// @file Axis-aligned bounding boxes.
#include <algorithm>
#include <limits>
#include <span>

#include <bimrock/geometry/vec2.hpp>

namespace bimrock {

struct BBox {
  Vec2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
  Vec2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void add(const Vec2& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  void add(const BBox& b) {
    lo = lo.cwiseMin(b.lo);
    hi = hi.cwiseMax(b.hi);
  }
  [[nodiscard]] bool empty() const { return lo.x() > hi.x(); }
  [[nodiscard]] double diagonal() const { return empty() ? 0.0 : (hi - lo).norm(); }
  /// True when p lies in the box grown by tol on every side.
  [[nodiscard]] bool contains(const Vec2& p, double tol = 0.0) const {
    return p.x() >= lo.x() - tol && p.x() <= hi.x() + tol && p.y() >= lo.y() - tol &&
           p.y() <= hi.y() + tol;
  }
};

inline BBox bbox_of(std::span<const Vec2> points) {
  BBox b;
  for (const Vec2& p : points)
    b.add(p);
  return b;
}

}  // namespace bimrock
