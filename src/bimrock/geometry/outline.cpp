#include <bimrock/geometry/outline.hpp>

#include <cmath>
#include <string>
#include <vector>

#include <CGAL/Polygon_2_algorithms.h>

#include <bimrock/geometry/exact_points.hpp>
#include <bimrock/geometry/geometry_error.hpp>

namespace bimrock {
namespace {

using exact::edge;
using exact::K;
using exact::point;
using exact::points;

std::string vertex_name(std::size_t k) {
  return "vertex " + std::to_string(k + 1);
}

// Two edges of one polygon may only meet where they share a vertex, and adjacent edges must not
// fold back onto each other. O(n^2) with a box test first: outlines have few vertices.
void check_simple(const Polygon& p, const std::string& item) {
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    const K::Segment_2 a = edge(p, i);
    const K::Segment_2 b = edge(p, (i + 1) % n);  // adjacent: shares vertex i+1
    if (CGAL::collinear(a.source(), a.target(), b.target()) &&
        (b.target() - b.source()) * (a.source() - a.target()) > 0)
      throw GeometryError(item, "the outline folds back on itself at " + vertex_name((i + 1) % n));
    const CGAL::Bbox_2 box_a = a.bbox();
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1)
        continue;  // adjacent through vertex 0
      const K::Segment_2 c = edge(p, j);
      if (!CGAL::do_overlap(box_a, c.bbox()))
        continue;
      if (CGAL::do_intersect(a, c))
        throw GeometryError(item, "the outline intersects itself: edges " + std::to_string(i + 1) +
                                      " and " + std::to_string(j + 1) + " cross or touch");
    }
  }
}

}  // namespace

void validate_outline(const Polygon& p, const std::string& item) {
  const std::size_t n = p.size();
  if (n < 3)
    throw GeometryError(item, "a polygon needs at least 3 vertices");
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(p.vertices[k].x()) || !std::isfinite(p.vertices[k].y()))
      throw GeometryError(item, vertex_name(k) + " is not a finite number");
  }
  for (std::size_t k = 0; k < n; ++k) {
    if (p.vertices[k] == p.vertices[(k + 1) % n])
      throw GeometryError(item, vertex_name((k + 1) % n) + " repeats the vertex before it");
  }
  check_simple(p, item);
  const std::vector<K::Point_2> pts = points(p);
  switch (CGAL::orientation_2(pts.begin(), pts.end(), K())) {
    case CGAL::COLLINEAR:
      throw GeometryError(item, "the polygon has zero area");
    case CGAL::CLOCKWISE:
      throw GeometryError(item, "the vertices are clockwise; list them counter-clockwise");
    default:
      break;
  }
}

bool outline_contains(const Polygon& outline, const Vec2& p, double tol) {
  const std::vector<K::Point_2> pts = points(outline);
  if (CGAL::bounded_side_2(pts.begin(), pts.end(), point(p), K()) != CGAL::ON_UNBOUNDED_SIDE)
    return true;
  for (std::size_t k = 0; k < outline.size(); ++k) {
    if (distance_to_segment(outline.edge(k), p) <= tol)
      return true;
  }
  return false;
}

}  // namespace bimrock
