#include <bimrock/geometry/cut_arrangement.hpp>

#include <algorithm>
#include <bit>
#include <cmath>
#include <deque>
#include <limits>

namespace bimrock::cut {

CurveTag MergeTags::operator()(const CurveTag& a, const CurveTag& b) const {
  CurveTag m;
  m.zones = a.zones ^ b.zones;
  m.boundary = a.boundary != b.boundary;
  m.rock_bridge = a.rock_bridge || b.rock_bridge;
  m.partition = a.partition || b.partition;
  // The lowest non-negative index of each (-1 stands for none).
  const auto lowest = [](std::int32_t i, std::int32_t j) {
    return (i < 0 || j < 0) ? std::max(i, j) : std::min(i, j);
  };
  m.trace = lowest(a.trace, b.trace);
  m.line = lowest(a.line, b.line);
  return m;
}

namespace {

void add_polygon(std::vector<Traits::Curve_2>& curves, const Polygon& p, CurveTag tag) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2& a = p.vertices[k];
    const Vec2& b = p.vertices[(k + 1) % p.size()];
    tag.line = static_cast<std::int32_t>(curves.size());
    curves.emplace_back(Kernel::Segment_2(Point(a.x(), a.y()), Point(b.x(), b.y())), tag);
  }
}

}  // namespace

void build(Arrangement& arr, const Domain& domain, std::span<const JointTrace> traces) {
  std::vector<Traits::Curve_2> curves;
  add_polygon(curves, domain.outline, {.boundary = true});
  for (const Polygon& h : domain.holes)
    add_polygon(curves, h, {.boundary = true});
  for (std::size_t z = 0; z < domain.zones.size(); ++z)
    add_polygon(curves, domain.zones[z].outline, {.zones = std::uint64_t{1} << z});
  for (std::size_t t = 0; t < traces.size(); ++t) {
    const Segment& s = traces[t].segment;
    if (s.a == s.b)
      continue;
    curves.emplace_back(Kernel::Segment_2(Point(s.a.x(), s.a.y()), Point(s.b.x(), s.b.y())),
                        CurveTag{.trace = static_cast<std::int32_t>(t),
                                 .line = static_cast<std::int32_t>(curves.size())});
  }
  CGAL::insert(arr, curves.begin(), curves.end());
  label_faces(arr);
}

void label_faces(Arrangement& arr) {
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    f->data() = FaceLabel{};
  std::deque<Face_handle> queue;
  Face_handle start = arr.unbounded_face();
  start->data().known = true;
  queue.push_back(start);
  while (!queue.empty()) {
    const Face_handle f = queue.front();
    queue.pop_front();
    for_each_boundary_halfedge(f, [&](Halfedge_handle h) {
      const Face_handle g = h->twin()->face();
      if (g->data().known)
        return;
      const CurveTag& tag = h->curve().data();
      g->data().known = true;
      g->data().inside = f->data().inside != tag.boundary;
      g->data().zones = f->data().zones ^ tag.zones;
      queue.push_back(g);
    });
  }
}

int first_zone(std::uint64_t zones) {
  return zones == 0 ? -1 : std::countr_zero(zones);
}

Vec2 to_vec2(const Point& p) {
  return {CGAL::to_double(p.x()), CGAL::to_double(p.y())};
}

std::vector<Halfedge_handle> boundary_halfedges(Face_handle f) {
  std::vector<Halfedge_handle> out;
  for_each_boundary_halfedge(f, [&](Halfedge_handle h) { out.push_back(h); });
  return out;
}

double face_area(Face_handle f) {
  // Shoelace over every cycle: the outer one runs counter-clockwise, holes clockwise, and the
  // two sides of an antenna cancel. Relative to one vertex to limit cancellation.
  bool first = true;
  Vec2 o = Vec2::Zero();
  double twice = 0.0;
  for_each_boundary_halfedge(f, [&](Halfedge_handle h) {
    const Vec2 a = to_vec2(h->source()->point());
    if (first)
      o = a;
    first = false;
    twice += cross(a - o, to_vec2(h->target()->point()) - o);
  });
  return 0.5 * twice;
}

}  // namespace bimrock::cut

namespace bimrock::cut {

void find_corners(Face_handle f, FaceCorners& out) {
  out.cycle.clear();
  out.corner_pos.clear();
  out.convex = true;
  out.reflex_deviation = 0.0;
  auto c = f->outer_ccb();
  const auto first = c;
  do {
    out.cycle.push_back(c);
  } while (++c != first);
  const std::size_t n = out.cycle.size();
  std::vector<bool>& right = out.turns_right;
  right.clear();
  for (std::size_t i = 0; i < n; ++i) {
    const Halfedge_handle in = out.cycle[(i + n - 1) % n];
    const Halfedge_handle h = out.cycle[i];
    const std::int32_t line = h->curve().data().line;
    if (line >= 0 && in->curve().data().line == line)
      continue;  // straight through
    const CGAL::Orientation o =
        CGAL::orientation(in->source()->point(), h->source()->point(), h->target()->point());
    if (o == CGAL::COLLINEAR)
      continue;
    out.corner_pos.push_back(i);
    right.push_back(o == CGAL::RIGHT_TURN);
    if (o == CGAL::RIGHT_TURN)
      out.convex = false;
  }
  // How far a reflex corner lies off the chord of its neighbouring corners (not its neighbouring
  // vertices, which may be a rounding error away on the same line).
  const std::size_t m = out.corner_pos.size();
  for (std::size_t k = 0; k < m; ++k) {
    if (!right[k])
      continue;
    const auto corner = [&](std::size_t j) -> const Point& {
      return out.cycle[out.corner_pos[j % m]]->source()->point();
    };
    out.reflex_deviation =
        std::max(out.reflex_deviation, deviation(corner(k + m - 1), corner(k), corner(k + 1)));
  }
}

double deviation(const Point& p, const Point& q, const Point& r) {
  const Vec2 a = to_vec2(p);
  const Vec2 b = to_vec2(q);
  const Vec2 c = to_vec2(r);
  // A turn back (by more than 90 degrees) is no small dent, however close q lies to the chord.
  if ((b - a).dot(c - b) <= 0.0)
    return std::numeric_limits<double>::infinity();
  const Vec2 d = c - a;
  return std::abs(cross(d, b - a)) / d.norm();
}

}  // namespace bimrock::cut
