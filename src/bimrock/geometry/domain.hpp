#pragma once
/// @file The rock domain to be cut into blocks: an outer outline, holes (tunnels, excavations)
/// and material zones. Outlines are simple polygons, not necessarily convex, stored in the
/// Polygon type with counter-clockwise vertices.
#include <string>
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {

/// A region of one rock material. Its edges inside the domain are internal boundaries: the
/// block cutter cuts along them, so no block straddles two zones. A zone may reach beyond the
/// domain (only its part inside counts), and zones may overlap: the first one listed wins.
struct Zone {
  std::string material;
  Polygon outline;  ///< simple, counter-clockwise
};

struct Domain {
  Polygon outline;             ///< simple, counter-clockwise
  std::vector<Polygon> holes;  ///< simple, counter-clockwise, strictly inside, pairwise apart
  std::vector<Zone> zones;     ///< at most kMaxZones; rock outside every zone has zone -1

  static constexpr int kMaxZones = 64;  ///< zone membership is a 64-bit mask in the cutter
};

/// Throws GeometryError naming the item ("domain.outline", "domain.holes[1]",
/// "domain.zones[0]") when: a polygon has fewer than 3 vertices, a non-finite or repeated
/// vertex, zero area, clockwise vertices, or edges that cross or overlap; a hole is not strictly
/// inside the outline; two holes touch or overlap; there are too many zones. Every test uses
/// exact predicates on the given doubles.
void validate(const Domain& domain);

/// Area of the outline less the holes.
double area(const Domain& domain);

/// Bounding box of the outline (holes lie inside it).
BBox bbox_of(const Domain& domain);

/// Index of the first zone whose outline strictly contains p, or -1.
int zone_containing(const Domain& domain, const Vec2& p);

}  // namespace bimrock
