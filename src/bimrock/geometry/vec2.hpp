#pragma once
/// @file Points and vectors of the plane. All lengths are in metres (SI, consistent units).
#include <Eigen/Core>

namespace bimrock {

using Vec2 = Eigen::Vector2d;

/// z-component of the cross product a x b (positive when b is counter-clockwise from a).
inline double cross(const Vec2& a, const Vec2& b) {
  return a.x() * b.y() - a.y() * b.x();
}

/// The vector turned 90 degrees counter-clockwise.
inline Vec2 perp(const Vec2& a) {
  return {-a.y(), a.x()};
}

}  // namespace bimrock
