#pragma once
/// @file Convex polygons: the shape of a block. Vertices counter-clockwise, in metres.
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include <bimrock/geometry/bbox.hpp>
#include <bimrock/geometry/segment.hpp>

namespace bimrock {

struct Polygon {
  std::vector<Vec2> vertices;  ///< counter-clockwise

  [[nodiscard]] std::size_t size() const { return vertices.size(); }
  /// Edge k runs from vertex k to vertex k+1 (cyclically).
  [[nodiscard]] Segment edge(std::size_t k) const {
    return {vertices[k], vertices[(k + 1) % vertices.size()]};
  }
};

/// Signed area (positive for counter-clockwise vertices), shoelace formula.
double signed_area(const Polygon& p);
/// Area centroid. @note undefined for zero area; check the polygon first.
Vec2 centroid(const Polygon& p);
BBox bbox_of(const Polygon& p);
/// Outward unit normal of edge k of a counter-clockwise polygon.
Vec2 outward_normal(const Polygon& p, std::size_t k);
/// True when p is inside the convex polygon or within tol of its boundary.
bool contains(const Polygon& poly, const Vec2& p, double tol);

/// What is wrong with a polygon that should be a block; `none` when it is a valid block.
enum class PolygonDefect {
  none,
  too_few_vertices,
  not_finite,
  duplicate_vertex,
  zero_area,
  clockwise,
  non_convex,
};

struct PolygonCheck {
  PolygonDefect defect = PolygonDefect::none;
  std::size_t vertex = 0;  ///< the offending vertex (0-based), where one can be named
};

/// The first vertex m that lies within tol of an earlier one (v.size() if none), in
/// O(n log n): check_convex_polygon's duplicate test, which a block of 1e6 vertices must pass.
/// The vertices must be finite.
std::size_t first_duplicate_vertex(std::span<const Vec2> v, double tol);

/// Checks that p is a convex, counter-clockwise polygon with at least 3 distinct vertices.
/// Collinear consecutive vertices (a T-junction on a straight side) are allowed.
/// @param tol length tolerance (see model_tolerance): closer vertices count as duplicates, a
///        vertex is reflex when it lies more than tol inside the line of its neighbours.
PolygonCheck check_convex_polygon(const Polygon& p, double tol);

/// A sentence a user can read, e.g. "vertex 3 makes the polygon non-convex".
std::string describe(const PolygonCheck& check);

/// The length tolerance of a model: 1e-9 times the diagonal of the bounding box of all blocks.
/// Points closer than this are the same point; segments closer than this to a line lie on it.
double model_tolerance(const BBox& model_box);

}  // namespace bimrock
