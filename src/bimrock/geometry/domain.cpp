#include <bimrock/geometry/domain.hpp>

#include <string>
#include <vector>

#include <CGAL/Polygon_2_algorithms.h>

#include <bimrock/geometry/exact_points.hpp>
#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/outline.hpp>

namespace bimrock {
namespace {

using exact::edge;
using exact::K;
using exact::point;
using exact::points;

bool edges_meet(const Polygon& a, const Polygon& b) {
  for (std::size_t i = 0; i < a.size(); ++i) {
    const K::Segment_2 s = edge(a, i);
    for (std::size_t j = 0; j < b.size(); ++j) {
      const K::Segment_2 t = edge(b, j);
      if (CGAL::do_overlap(s.bbox(), t.bbox()) && CGAL::do_intersect(s, t))
        return true;
    }
  }
  return false;
}

CGAL::Bounded_side side_of(const Polygon& poly, const Vec2& p) {
  const std::vector<K::Point_2> pts = points(poly);
  return CGAL::bounded_side_2(pts.begin(), pts.end(), point(p), K());
}

}  // namespace

void validate(const Domain& d) {
  validate_outline(d.outline, "domain.outline");
  for (std::size_t h = 0; h < d.holes.size(); ++h) {
    const std::string item = "domain.holes[" + std::to_string(h) + "]";
    validate_outline(d.holes[h], item);
    // Edges apart and one vertex inside: the whole hole is strictly inside the outline.
    if (edges_meet(d.holes[h], d.outline))
      throw GeometryError(item, "the hole touches or crosses the domain outline");
    if (side_of(d.outline, d.holes[h].vertices.front()) != CGAL::ON_BOUNDED_SIDE)
      throw GeometryError(item, "the hole lies outside the domain");
    for (std::size_t g = 0; g < h; ++g) {
      const std::string other = "domain.holes[" + std::to_string(g) + "]";
      if (edges_meet(d.holes[h], d.holes[g]) ||
          side_of(d.holes[g], d.holes[h].vertices.front()) != CGAL::ON_UNBOUNDED_SIDE ||
          side_of(d.holes[h], d.holes[g].vertices.front()) != CGAL::ON_UNBOUNDED_SIDE)
        throw GeometryError(item, "the hole touches or overlaps " + other);
    }
  }
  if (d.zones.size() > static_cast<std::size_t>(Domain::kMaxZones))
    throw GeometryError("domain.zones",
                        "at most " + std::to_string(Domain::kMaxZones) + " zones are supported");
  for (std::size_t z = 0; z < d.zones.size(); ++z)
    validate_outline(d.zones[z].outline, "domain.zones[" + std::to_string(z) + "]");
}

double area(const Domain& d) {
  double a = signed_area(d.outline);
  for (const Polygon& h : d.holes)
    a -= signed_area(h);
  return a;
}

BBox bbox_of(const Domain& d) {
  return bbox_of(d.outline);
}

int zone_containing(const Domain& d, const Vec2& p) {
  for (std::size_t z = 0; z < d.zones.size(); ++z) {
    if (side_of(d.zones[z].outline, p) == CGAL::ON_BOUNDED_SIDE)
      return static_cast<int>(z);
  }
  return -1;
}

}  // namespace bimrock
