#include <bimrock/geometry/polygon.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace bimrock {

double signed_area(const Polygon& p) {
  // Shoelace relative to the first vertex: exact-ish far from the origin (coordinates in UTM).
  const Vec2 o = p.vertices.front();
  double twice = 0.0;
  const std::size_t n = p.size();
  for (std::size_t k = 1; k + 1 < n; ++k)
    twice += cross(p.vertices[k] - o, p.vertices[k + 1] - o);
  return 0.5 * twice;
}

Vec2 centroid(const Polygon& p) {
  // Shoelace centroid, taken relative to the first vertex to limit cancellation far from origin.
  const Vec2 o = p.vertices.front();
  const std::size_t n = p.size();
  double twice_area = 0.0;
  Vec2 sum = Vec2::Zero();
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = p.vertices[k] - o;
    const Vec2 b = p.vertices[(k + 1) % n] - o;
    const double c = cross(a, b);
    twice_area += c;
    sum += c * (a + b);
  }
  return o + sum / (3.0 * twice_area);
}

BBox bbox_of(const Polygon& p) {
  return bbox_of(std::span<const Vec2>(p.vertices));
}

Vec2 outward_normal(const Polygon& p, std::size_t k) {
  const Segment e = p.edge(k);
  const Vec2 t = e.direction();
  return {t.y(), -t.x()};  // right of the edge is outside for counter-clockwise vertices
}

bool contains(const Polygon& poly, const Vec2& p, double tol) {
  for (std::size_t k = 0; k < poly.size(); ++k) {
    if (outward_normal(poly, k).dot(p - poly.vertices[k]) > tol)
      return false;
  }
  return true;
}

std::size_t first_duplicate_vertex(std::span<const Vec2> v, double tol) {
  const std::size_t n = v.size();
  const auto close = [&](std::size_t k, std::size_t m) { return (v[k] - v[m]).norm() <= tol; };
  // A few vertices (every block but an imported outline): all pairs, no allocation.
  constexpr std::size_t kAllPairsUpTo = 32;
  const BBox box = bbox_of(v);
  const double extent = std::max(box.hi.x() - box.lo.x(), box.hi.y() - box.lo.y());
  if (n <= kAllPairsUpTo || !std::isfinite(extent)) {
    for (std::size_t m = 1; m < n; ++m) {
      for (std::size_t k = 0; k < m; ++k) {
        if (close(k, m))
          return m;
      }
    }
    return n;
  }
  if (extent == 0.0)
    return 1;  // every vertex is the first one
  // Cells of side h a little over tol (rounding of the cell index may not split a close pair
  // more than one cell apart): a vertex's close vertices lie in its 3 x 3 cells. A cell holds
  // at most 4 vertices more than tol apart (its four quarters are narrower than tol), so among
  // the first 5 vertices of a cell two are close: the later ones cannot be the first duplicate,
  // nor its earlier partner, and are dropped. So each vertex meets at most 45 others: O(n log n)
  // for the sort, O(n) after it. A tolerance below 2^-40 of the extent (0 in tests) makes the cells
  // larger than tol: still exact, without that bound.
  constexpr double kMaxCells = 0x1p40;
  const bool fine = tol > 0.0 && extent / (1.01 * tol) <= kMaxCells;
  const double h = fine ? 1.01 * tol : extent / kMaxCells;
  const std::size_t per_cell = fine ? 5 : n;
  struct Entry {
    std::int64_t cx, cy;
    std::size_t index;
    auto operator<=>(const Entry&) const = default;
  };
  std::vector<Entry> cells(n);
  for (std::size_t k = 0; k < n; ++k) {
    cells[k] = {static_cast<std::int64_t>(std::floor((v[k].x() - box.lo.x()) / h)),
                static_cast<std::int64_t>(std::floor((v[k].y() - box.lo.y()) / h)), k};
  }
  std::sort(cells.begin(), cells.end());
  std::size_t kept = 0;
  for (std::size_t k = 0, run = 0; k < n; ++k) {
    run = k > 0 && cells[k].cx == cells[k - 1].cx && cells[k].cy == cells[k - 1].cy ? run + 1 : 0;
    if (run < per_cell)
      cells[kept++] = cells[k];
  }
  cells.resize(kept);
  // The cells are visited in order, so the first candidate of each column dx (cell
  // (cx + dx, cy - 1)) only moves forward: one cursor per column.
  std::size_t first = n;
  std::size_t cursor[3] = {0, 0, 0};
  for (const Entry& e : cells) {
    for (std::int64_t dx = -1; dx <= 1; ++dx) {
      std::size_t& c = cursor[dx + 1];
      const Entry from{e.cx + dx, e.cy - 1, 0};
      while (c < cells.size() && cells[c] < from)
        ++c;
      // (Once e is a duplicate, or a later vertex than one found, its scan ends: the coarse
      // cells, without the 5 per cell, then stay linear for repeated vertices too.)
      for (std::size_t k = c; e.index < first && k < cells.size() && cells[k].cx == e.cx + dx &&
                              cells[k].cy <= e.cy + 1;
           ++k) {
        if (cells[k].index < e.index && close(cells[k].index, e.index))
          first = e.index;
      }
    }
  }
  return first;
}

PolygonCheck check_convex_polygon(const Polygon& p, double tol) {
  const std::size_t n = p.size();
  if (n < 3)
    return {PolygonDefect::too_few_vertices, 0};
  for (std::size_t k = 0; k < n; ++k) {
    if (!std::isfinite(p.vertices[k].x()) || !std::isfinite(p.vertices[k].y()))
      return {PolygonDefect::not_finite, k};
  }
  if (const std::size_t m = first_duplicate_vertex(p.vertices, tol); m < n)
    return {PolygonDefect::duplicate_vertex, m};
  const double area = signed_area(p);
  BBox box = bbox_of(p);
  if (std::abs(area) <= tol * box.diagonal())
    return {PolygonDefect::zero_area, 0};
  if (area < 0.0)
    return {PolygonDefect::clockwise, 0};
  // Convex: every vertex lies on or left of the line through its two neighbours' edges.
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2& prev = p.vertices[(k + n - 1) % n];
    const Vec2& cur = p.vertices[k];
    const Vec2& next = p.vertices[(k + 1) % n];
    const Vec2 d = next - prev;
    // A convex vertex lies right of the chord prev->next (negative distance); reflex when left.
    const double dist = cross(d, cur - prev) / d.norm();
    if (dist > tol)
      return {PolygonDefect::non_convex, k};
  }
  // A polygon that winds more than once (a star) passes the local test: count the turning.
  double turning = 0.0;
  for (std::size_t k = 0; k < n; ++k) {
    const Vec2 a = p.vertices[(k + 1) % n] - p.vertices[k];
    const Vec2 b = p.vertices[(k + 2) % n] - p.vertices[(k + 1) % n];
    turning += std::atan2(cross(a, b), a.dot(b));
  }
  if (std::abs(turning - 2.0 * M_PI) > 1e-6)
    return {PolygonDefect::non_convex, 0};
  return {};
}

std::string describe(const PolygonCheck& c) {
  const std::string v = "vertex " + std::to_string(c.vertex + 1);
  switch (c.defect) {
    case PolygonDefect::none:
      return "valid convex polygon";
    case PolygonDefect::too_few_vertices:
      return "a polygon needs at least 3 vertices";
    case PolygonDefect::not_finite:
      return v + " is not a finite number (NaN or infinity)";
    case PolygonDefect::duplicate_vertex:
      return v + " duplicates an earlier vertex";
    case PolygonDefect::zero_area:
      return "the polygon has zero area";
    case PolygonDefect::clockwise:
      return "the vertices are clockwise; list them counter-clockwise";
    case PolygonDefect::non_convex:
      return v + " makes the polygon non-convex";
  }
  return "unknown defect";
}

double model_tolerance(const BBox& model_box) {
  return 1e-9 * model_box.diagonal();
}

}  // namespace bimrock
