#include <bimrock/geometry/face_cuts.hpp>

#include <optional>
#include <stdexcept>

namespace bimrock::cut {
namespace {

using Vector = Kernel::Vector_2;

// True when dir lies strictly inside the sector of h->face() at h->target(): the sector swept
// counter-clockwise from the outgoing edge h->next() to the incoming edge h, reversed.
bool sector_contains(Halfedge_handle h, const Vector& dir) {
  const Point& t = h->target()->point();
  const Vector a = h->next()->target()->point() - t;
  const Vector b = h->source()->point() - t;
  const auto turn = [](const Vector& u, const Vector& v) { return CGAL::orientation(u, v); };
  switch (turn(a, b)) {
    case CGAL::LEFT_TURN:  // convex sector
      return turn(a, dir) == CGAL::LEFT_TURN && turn(dir, b) == CGAL::LEFT_TURN;
    case CGAL::RIGHT_TURN:  // reflex sector: outside the closed convex sector from b to a
      return !(turn(b, dir) != CGAL::RIGHT_TURN && turn(dir, a) != CGAL::RIGHT_TURN);
    default:
      if (a * b > 0)  // the tip of an antenna: every direction but back along the edge
        return !(turn(a, dir) == CGAL::COLLINEAR && a * dir > 0);
      return turn(a, dir) == CGAL::LEFT_TURN;  // a straight angle
  }
}

struct Hit {
  Point point;
  Halfedge_handle edge;                 // the edge hit
  std::optional<Vertex_handle> vertex;  // set when the hit is one of its end vertices
};

// First point where the ray from s meets the boundary of face f. Only f's own cycles can be
// met first: the ray starts inside f.
std::optional<Hit> first_hit(Face_handle f, Vertex_handle s, const Kernel::Ray_2& ray) {
  std::optional<Hit> best;
  const Point& origin = s->point();
  const auto consider = [&](const Point& p, Halfedge_handle e) {
    if (best && CGAL::compare_distance_to_point(origin, p, best->point) != CGAL::SMALLER)
      return;
    best = Hit{p, e, std::nullopt};
    if (p == e->source()->point())
      best->vertex = e->source();
    if (p == e->target()->point())
      best->vertex = e->target();
  };
  const Point ahead = origin + ray.to_vector();
  for_each_boundary_halfedge(f, [&](Halfedge_handle e) {
    if (e->source() == s || e->target() == s)
      return;  // they touch the ray at s only
    // An edge wholly on one side of the ray's line is not met. Two orientation tests, which the
    // interval filter decides, say so; do_intersect itself intersects the two lines, which for
    // an edge parallel to the ray (a joint of a parallel set) needs exact arithmetic on the
    // corners' construction history.
    const CGAL::Orientation side = CGAL::orientation(origin, ahead, e->source()->point());
    if (side != CGAL::COLLINEAR && side == CGAL::orientation(origin, ahead, e->target()->point()))
      return;
    const Kernel::Segment_2 seg(e->source()->point(), e->target()->point());
    if (!CGAL::do_intersect(ray, seg))
      return;
    const auto x = CGAL::intersection(ray, seg);
    if (const Point* p = boost::get<Point>(&*x)) {
      consider(*p, e);
    } else if (const auto* overlap = boost::get<Kernel::Segment_2>(&*x)) {
      const bool first =
          CGAL::has_smaller_distance_to_point(origin, overlap->source(), overlap->target());
      consider(first ? overlap->source() : overlap->target(), e);
    }
  });
  return best;
}

// The halfedge of `cycle` whose target is the top (bottom) vertex, largest (smallest) in (y, x)
// order, and whose sector holds the vertical direction; none when that vertex is `avoid`. No
// point of the cycle lies straight above its top vertex, so a cut up from there leaves it.
std::optional<Halfedge_handle> extreme(const std::vector<Halfedge_handle>& cycle, bool top,
                                       std::optional<Vertex_handle> avoid, const Vector& dir) {
  Vertex_handle best = cycle.front()->target();
  for (const Halfedge_handle h : cycle) {
    const CGAL::Comparison_result c = CGAL::compare_yx(h->target()->point(), best->point());
    if ((top && c == CGAL::LARGER) || (!top && c == CGAL::SMALLER))
      best = h->target();
  }
  if (avoid && best == *avoid)
    return std::nullopt;
  for (const Halfedge_handle h : cycle) {
    if (h->target() == best && sector_contains(h, dir))
      return h;
  }
  return std::nullopt;
}

// Minimal closed sub-cycles of a boundary cycle that visits some vertex more than once (empty
// when it visits every vertex once). Uses the vertices' int field as scratch.
std::vector<std::vector<Halfedge_handle>> sub_cycles(const std::vector<Halfedge_handle>& cycle) {
  std::vector<std::vector<Halfedge_handle>> loops;
  std::vector<Halfedge_handle> stack{cycle.back()};  // its target is where the cycle starts
  for (const Halfedge_handle h : cycle)
    h->target()->data() = -1;
  cycle.back()->target()->data() = 0;
  for (const Halfedge_handle h : cycle) {
    const int at = h->target()->data();
    if (at < 0) {
      h->target()->data() = static_cast<int>(stack.size());
      stack.push_back(h);
      continue;
    }
    std::vector<Halfedge_handle> loop(stack.begin() + at + 1, stack.end());
    loop.push_back(h);
    for (std::size_t k = static_cast<std::size_t>(at) + 1; k < stack.size(); ++k)
      stack[k]->target()->data() = -1;
    stack.resize(static_cast<std::size_t>(at) + 1);
    loops.push_back(std::move(loop));
  }
  for (const Halfedge_handle h : cycle)
    h->target()->data() = -1;
  if (loops.size() == 1)
    loops.clear();  // the whole cycle closed once: simple
  return loops;
}

double cycle_area(const std::vector<Halfedge_handle>& cycle) {
  const Vec2 o = to_vec2(cycle.front()->source()->point());
  double twice = 0.0;
  for (const Halfedge_handle h : cycle)
    twice += cross(to_vec2(h->source()->point()) - o, to_vec2(h->target()->point()) - o);
  return 0.5 * twice;
}

// One cut that makes progress on a face that is not simple; false when it is simple.
bool cut_once(Arrangement& arr, Face_handle f, std::vector<Face_handle>& new_faces) {
  const Vector up(0, 1);
  const Vector down(0, -1);
  std::vector<Halfedge_handle> cycle;
  std::optional<Vertex_handle> attachment;
  if (f->number_of_inner_ccbs() > 0) {
    auto c = *f->inner_ccbs_begin();
    const auto first = c;
    do {
      cycle.push_back(c);
    } while (++c != first);
  } else {
    auto c = f->outer_ccb();
    const auto first = c;
    std::vector<Halfedge_handle> outer;
    do {
      outer.push_back(c);
    } while (++c != first);
    // A clockwise sub-cycle is a hole attached to the rest at one vertex (its last target).
    for (auto& loop : sub_cycles(outer)) {
      if (loop.size() >= 3 && cycle_area(loop) < 0.0) {
        attachment = loop.back()->target();
        cycle = std::move(loop);
        break;
      }
    }
    if (cycle.empty())
      return false;
  }
  std::optional<Halfedge_handle> h = extreme(cycle, true, attachment, up);
  Vector dir = up;
  if (!h) {
    h = extreme(cycle, false, attachment, down);
    dir = down;
  }
  if (!h)
    throw std::logic_error("block cutter: no vertical cut leaves a hole of a face");
  const Halfedge_handle e = cut_along_ray(arr, *h, dir);
  if (e->face() != e->twin()->face())
    new_faces.push_back(e->face() == f ? e->twin()->face() : e->face());
  return true;
}

}  // namespace

Halfedge_handle cut_along_ray(Arrangement& arr, Halfedge_handle h, const Vector& dir,
                              std::int32_t line) {
  const Vertex_handle s = h->target();
  const Face_handle f = h->face();
  const FaceLabel label = f->data();
  const std::optional<Hit> hit = first_hit(f, s, Kernel::Ray_2(s->point(), dir));
  if (!hit)
    throw std::logic_error("block cutter: a cut from inside a face met no edge");
  Vertex_handle v;
  if (hit->vertex) {
    v = *hit->vertex;
  } else {
    Traits::X_monotone_curve_2 c1;
    Traits::X_monotone_curve_2 c2;
    arr.geometry_traits()->split_2_object()(hit->edge->curve(), hit->point, c1, c2);
    v = arr.split_edge(hit->edge, c1, c2)->target();
    v->data() = -1;  // the scratch field of a new vertex is not initialised
  }
  const Traits::X_monotone_curve_2 cut(Traits::Base_x_monotone_curve_2(s->point(), v->point()),
                                       CurveTag{.line = line, .rock_bridge = true});
  const Halfedge_handle e = arr.insert_at_vertices(cut, h, v);
  e->face()->data() = label;
  e->twin()->face()->data() = label;
  return e->source() == s ? e : e->twin();
}

int extend_dangling_ends(Arrangement& arr) {
  std::vector<Vertex_handle> tips;
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v) {
    if (v->degree() == 1 && v->incident_halfedges()->face()->data().inside)
      tips.push_back(v);
  }
  int n = 0;
  for (const Vertex_handle tip : tips) {
    if (tip->degree() != 1)
      continue;                                           // an earlier extension ended on it
    const Halfedge_handle h = tip->incident_halfedges();  // ends at the tip
    cut_along_ray(arr, h, tip->point() - h->source()->point(), h->curve().data().line);
    ++n;
  }
  return n;
}

// True when f has no hole and its outer cycle visits every vertex once (the common case,
// decided without allocating). Marks visited vertices with `stamp`.
bool is_simple(Face_handle f, int stamp) {
  if (f->number_of_inner_ccbs() > 0)
    return false;
  auto c = f->outer_ccb();
  const auto first = c;
  do {
    if (c->target()->data() == stamp)
      return false;
    c->target()->data() = stamp;
  } while (++c != first);
  return true;
}

int make_faces_simple(Arrangement& arr) {
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
    v->data() = -1;
  std::vector<Face_handle> work;
  int stamp = 0;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    if (f->data().inside && !is_simple(f, stamp++))
      work.push_back(f);
  for (auto v = arr.vertices_begin(); v != arr.vertices_end(); ++v)
    v->data() = -1;
  int n = 0;
  while (!work.empty()) {
    const Face_handle f = work.back();
    work.pop_back();
    std::vector<Face_handle> new_faces;
    while (cut_once(arr, f, new_faces))
      ++n;
    work.insert(work.end(), new_faces.begin(), new_faces.end());
  }
  return n;
}

}  // namespace bimrock::cut
