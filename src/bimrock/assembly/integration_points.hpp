#pragma once
/// @file Integration points along an interface segment for the chosen rule (docs/formulation.md).
#include <array>

#include <bimrock/geometry/segment.hpp>
#include <bimrock/model/materials.hpp>

namespace bimrock {

struct IntegrationPoint {
  Vec2 point;
  double weight;  ///< length represented by the point [m]
};

/// Two points per segment: end points with weights L/2 (Lobatto / trapezoid) or the 2-point
/// Gauss points (1 -+ 1/sqrt 3) / 2 with weights L/2. Both integrate a linear field exactly;
/// Gauss also integrates B^T D B (quadratic) exactly.
std::array<IntegrationPoint, 2> integration_points(const Segment& s, Integration rule);

}  // namespace bimrock
