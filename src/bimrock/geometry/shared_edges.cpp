#include <bimrock/geometry/shared_edges.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

#include <CGAL/box_intersection_d.h>

namespace bimrock {
namespace {

using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 2, std::size_t,
                                                        CGAL::Box_intersection_d::ID_EXPLICIT>;

// Overlap of edge a (of polygon i) with edge b (of polygon j): the part of a that b covers, as a
// parameter interval [t0, t1] along a. Empty when the edges are not anti-parallel and collinear.
bool collinear_overlap(const Segment& a, const Segment& b, double tol, double& t0, double& t1) {
  const Vec2 da = a.b - a.a;
  const double la = da.norm();
  const Vec2 ua = da / la;
  const Vec2 db = b.b - b.a;
  if (ua.dot(db) >= 0.0)
    return false;  // neighbours traverse a shared edge in opposite senses
  if (std::abs(cross(ua, b.a - a.a)) > tol || std::abs(cross(ua, b.b - a.a)) > tol)
    return false;
  const double sb0 = ua.dot(b.a - a.a);
  const double sb1 = ua.dot(b.b - a.a);
  const double s0 = std::max(0.0, std::min(sb0, sb1));
  const double s1 = std::min(la, std::max(sb0, sb1));
  if (s1 - s0 <= tol)
    return false;
  t0 = s0 / la;
  t1 = s1 / la;
  return true;
}

// Two polygons whose edge pairs exceed this are searched by box intersection of their edges
// (edge_pairs) and by their hull (min_over), not pair by pair: two blocks of 2e4 vertices
// took 2.9 s with all 4e8 pairs. Below it, every pair, as always.
constexpr std::size_t kAllPairsUpTo = 4096;

// The pairs (edge of p, edge of q) whose bounding boxes, grown by `grow`, meet: every pair,
// or those of a box intersection of the edges for large polygons, sorted as the loops over
// p's then q's edges would give them.
std::vector<std::pair<int, int>> edge_pairs(const Polygon& p, const Polygon& q, double grow) {
  std::vector<std::pair<int, int>> pairs;
  if (p.size() * q.size() <= kAllPairsUpTo) {
    for (std::size_t a = 0; a < p.size(); ++a) {
      for (std::size_t b = 0; b < q.size(); ++b)
        pairs.emplace_back(static_cast<int>(a), static_cast<int>(b));
    }
    return pairs;
  }
  const auto boxes = [grow](const Polygon& poly) {
    std::vector<Box> out;
    out.reserve(poly.size());
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Segment e = poly.edge(k);
      double lo[2] = {std::min(e.a.x(), e.b.x()) - grow, std::min(e.a.y(), e.b.y()) - grow};
      double hi[2] = {std::max(e.a.x(), e.b.x()) + grow, std::max(e.a.y(), e.b.y()) + grow};
      out.emplace_back(lo, hi, k);
    }
    return out;
  };
  std::vector<Box> edges_p = boxes(p);
  std::vector<Box> edges_q = boxes(q);
  CGAL::box_intersection_d(
      edges_p.begin(), edges_p.end(), edges_q.begin(), edges_q.end(),
      [&](const Box& a, const Box& b) {
        pairs.emplace_back(static_cast<int>(a.handle()), static_cast<int>(b.handle()));
      },
      std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

// The counter-clockwise convex hull of a polygon's vertices (Andrew's monotone chain; collinear
// vertices dropped), as indices.
std::vector<std::size_t> hull_of(const Polygon& q) {
  std::vector<std::size_t> order(q.size());
  for (std::size_t k = 0; k < order.size(); ++k)
    order[k] = k;
  const auto& v = q.vertices;
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    return v[a].x() < v[b].x() || (v[a].x() == v[b].x() && v[a].y() < v[b].y());
  });
  std::vector<std::size_t> hull(2 * order.size());
  std::size_t k = 0;
  const auto turn = [&](std::size_t o, std::size_t a, std::size_t b) {
    return cross(v[a] - v[o], v[b] - v[o]);
  };
  for (const std::size_t i : order) {  // lower hull
    while (k >= 2 && turn(hull[k - 2], hull[k - 1], i) <= 0.0)
      --k;
    hull[k++] = i;
  }
  for (std::size_t t = order.size() - 1, lower = k + 1; t-- > 0;) {  // upper hull
    const std::size_t i = order[t];
    while (k >= lower && turn(hull[k - 2], hull[k - 1], i) <= 0.0)
      --k;
    hull[k++] = i;
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

}  // namespace

std::vector<std::pair<int, int>> candidate_pairs(std::span<const Polygon> polygons, double tol) {
  std::vector<Box> boxes;
  boxes.reserve(polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const BBox b = bbox_of(polygons[k]);
    double lo[2] = {b.lo.x() - tol, b.lo.y() - tol};
    double hi[2] = {b.hi.x() + tol, b.hi.y() + tol};
    boxes.emplace_back(lo, hi, k);
  }
  std::vector<std::pair<int, int>> pairs;
  auto report = [&](const Box& a, const Box& b) {
    const int i = static_cast<int>(a.handle());
    const int j = static_cast<int>(b.handle());
    pairs.emplace_back(std::min(i, j), std::max(i, j));
  };
  // Closed boxes: blocks that only touch still form a candidate pair.
  CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report, std::ptrdiff_t(10),
                                CGAL::Box_intersection_d::CLOSED);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

std::vector<int> first_containing(std::span<const Polygon> polygons, std::span<const Vec2> points,
                                  double tol) {
  std::vector<int> first(points.size(), -1);
  if (polygons.empty() || points.empty())
    return first;
  std::vector<Box> blocks;
  blocks.reserve(polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    const BBox b = bbox_of(polygons[k]);
    double lo[2] = {b.lo.x() - tol, b.lo.y() - tol};
    double hi[2] = {b.hi.x() + tol, b.hi.y() + tol};
    blocks.emplace_back(lo, hi, k);
  }
  std::vector<Box> at;
  at.reserve(points.size());
  for (std::size_t k = 0; k < points.size(); ++k) {
    double p[2] = {points[k].x(), points[k].y()};
    at.emplace_back(p, p, k);
  }
  auto report = [&](const Box& block, const Box& point) {
    const int b = static_cast<int>(block.handle());
    int& f = first[point.handle()];
    if ((f < 0 || b < f) && contains(polygons[b], points[point.handle()], tol))
      f = b;
  };
  // Closed boxes: a point on a block's bounding box (a vertex, an edge) is a candidate.
  CGAL::box_intersection_d(blocks.begin(), blocks.end(), at.begin(), at.end(), report,
                           std::ptrdiff_t(10), CGAL::Box_intersection_d::CLOSED);
  return first;
}

std::vector<SharedEdge> find_shared_edges(std::span<const Polygon> polygons, double tol) {
  std::vector<SharedEdge> shared;
  for (const auto& [i, j] : candidate_pairs(polygons, tol)) {
    const Polygon& pi = polygons[i];
    const Polygon& pj = polygons[j];
    // Edges that share a segment longer than tol pass within tol of each other: their boxes
    // grown by tol meet (2 tol: rounding of the distances).
    for (const auto& [ei, ej] : edge_pairs(pi, pj, 2.0 * tol)) {
      const Segment a = pi.edge(static_cast<std::size_t>(ei));
      double t0 = 0.0;
      double t1 = 0.0;
      if (!collinear_overlap(a, pj.edge(static_cast<std::size_t>(ej)), tol, t0, t1))
        continue;
      shared.push_back(
          {i, j, ei, ej, {a.at(t0), a.at(t1)}, outward_normal(pi, static_cast<std::size_t>(ei))});
    }
  }
  return shared;
}

std::vector<BoundaryEdge> find_boundary_edges(std::span<const Polygon> polygons,
                                              std::span<const SharedEdge> shared, double tol) {
  // Covered parameter intervals per (polygon, edge), from both sides of every shared segment.
  std::vector<std::vector<std::vector<std::pair<double, double>>>> covered(polygons.size());
  for (std::size_t k = 0; k < polygons.size(); ++k)
    covered[k].resize(polygons[k].size());
  auto cover = [&](int poly, int edge, const Segment& s) {
    const Segment e = polygons[poly].edge(edge);
    const Vec2 d = e.b - e.a;
    const double l2 = d.squaredNorm();
    double t0 = (s.a - e.a).dot(d) / l2;
    double t1 = (s.b - e.a).dot(d) / l2;
    if (t0 > t1)
      std::swap(t0, t1);
    covered[poly][edge].emplace_back(t0, t1);
  };
  for (const SharedEdge& s : shared) {
    cover(s.i, s.edge_i, s.segment);
    cover(s.j, s.edge_j, s.segment);
  }
  std::vector<BoundaryEdge> boundary;
  for (std::size_t k = 0; k < polygons.size(); ++k) {
    for (std::size_t e = 0; e < polygons[k].size(); ++e) {
      const Segment edge = polygons[k].edge(e);
      const double len = edge.length();
      auto& intervals = covered[k][e];
      std::sort(intervals.begin(), intervals.end());
      double t = 0.0;
      auto emit = [&](double t_end) {
        if ((t_end - t) * len > tol) {
          boundary.push_back({static_cast<int>(k),
                              static_cast<int>(e),
                              {edge.at(t), edge.at(t_end)},
                              outward_normal(polygons[k], e)});
        }
      };
      for (const auto& [a, b] : intervals) {
        if (a > t)
          emit(a);
        t = std::max(t, b);
      }
      emit(1.0);
    }
  }
  return boundary;
}

std::vector<std::pair<int, int>> find_overlaps(std::span<const Polygon> polygons, double tol) {
  // Two convex polygons overlap unless an edge normal of one separates them (by at least -tol).
  auto separated_by_edges_of = [tol](const Polygon& p, const Polygon& q) {
    if (p.size() * q.size() <= kAllPairsUpTo) {
      for (std::size_t e = 0; e < p.size(); ++e) {
        const Vec2 n = outward_normal(p, e);
        const Vec2& o = p.vertices[e];
        double min_q = std::numeric_limits<double>::infinity();
        for (const Vec2& v : q.vertices)
          min_q = std::min(min_q, n.dot(v - o));
        if (min_q >= -tol)
          return true;
      }
      return false;
    }
    // Large polygons: the least n.v over q's vertices is over its hull's, where n.v falls then
    // rises round the hull; p's normals turn with its edges, so the least vertex of the last
    // edge, moved downhill either way, is the next one's (about one turn round the hull in all).
    const std::vector<std::size_t> hull = hull_of(q);
    const std::size_t h = hull.size();
    std::size_t at = 0;
    for (std::size_t e = 0; e < p.size(); ++e) {
      const Vec2 n = outward_normal(p, e);
      const auto value = [&](std::size_t k) { return n.dot(q.vertices[hull[k % h]]); };
      if (e == 0) {
        for (std::size_t k = 1; k < h; ++k)
          at = value(k) < value(at) ? k : at;
      }
      for (bool moved = true; moved;) {
        moved = false;
        while (value(at + 1) < value(at)) {
          at = (at + 1) % h;
          moved = true;
        }
        while (value(at + h - 1) < value(at)) {
          at = (at + h - 1) % h;
          moved = true;
        }
      }
      if (value(at) - n.dot(p.vertices[e]) >= -tol)
        return true;
    }
    return false;
  };
  std::vector<std::pair<int, int>> overlaps;
  for (const auto& [i, j] : candidate_pairs(polygons, tol)) {
    if (!separated_by_edges_of(polygons[i], polygons[j]) &&
        !separated_by_edges_of(polygons[j], polygons[i]))
      overlaps.emplace_back(i, j);
  }
  return overlaps;
}

}  // namespace bimrock
