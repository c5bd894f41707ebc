#pragma once
/// @file Polygons as CGAL points of the exact-predicates kernel, for the checks of outlines and
/// domains: exact predicates on the input doubles, so that validation never depends on a
/// tolerance.
#include <cstddef>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock::exact {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

inline K::Point_2 point(const Vec2& v) {
  return {v.x(), v.y()};
}

/// Edge k of p, from vertex k to the next.
inline K::Segment_2 edge(const Polygon& p, std::size_t k) {
  return {point(p.vertices[k]), point(p.vertices[(k + 1) % p.size()])};
}

inline std::vector<K::Point_2> points(const Polygon& p) {
  std::vector<K::Point_2> out;
  out.reserve(p.size());
  for (const Vec2& v : p.vertices)
    out.push_back(point(v));
  return out;
}

}  // namespace bimrock::exact
