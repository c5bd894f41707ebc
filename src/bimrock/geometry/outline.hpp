#pragma once
/// @file Outlines: simple polygons, not necessarily convex, counter-clockwise. A domain's
/// outline, holes and zones are outlines, and so is the region a stage excavates or installs.
#include <string>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {

/// Throws GeometryError naming `item` when p is not an outline: fewer than 3 vertices, a
/// non-finite vertex or one repeating the vertex before it, edges that cross, touch or fold back
/// onto each other, zero area, clockwise vertices. Exact predicates on the given doubles: the
/// check never depends on a tolerance.
void validate_outline(const Polygon& p, const std::string& item);

/// True when p lies inside the outline or within tol of its boundary.
bool outline_contains(const Polygon& outline, const Vec2& p, double tol);

}  // namespace bimrock
