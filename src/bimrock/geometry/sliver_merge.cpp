#include <bimrock/geometry/sliver_merge.hpp>

#include <algorithm>
#include <functional>
#include <optional>
#include <queue>
#include <tuple>
#include <utility>

namespace bimrock::cut {
namespace {

struct Neighbour {
  Face_handle face;
  double shared_length = 0.0;
  bool same_zones = false;
  bool convex_union = true;
};

// The start of the straight run of boundary that ends with halfedge h: the corner before it.
const Point& run_start(Halfedge_handle h) {
  Halfedge_handle e = h;
  for (std::size_t k = 0; k < 1000; ++k) {  // bounded: a cycle that is all one line cannot be
    const Halfedge_handle p = e->prev();
    const std::int32_t line = e->curve().data().line;
    const bool straight = (line >= 0 && p->curve().data().line == line) ||
                          CGAL::orientation(p->source()->point(), e->source()->point(),
                                            e->target()->point()) == CGAL::COLLINEAR;
    if (!straight)
      break;
    e = p;
  }
  return e->source()->point();
}

// The end of the straight run of boundary that starts with halfedge h: the corner after it.
const Point& run_end(Halfedge_handle h) {
  Halfedge_handle e = h;
  for (std::size_t k = 0; k < 1000; ++k) {
    const Halfedge_handle n = e->next();
    const std::int32_t line = e->curve().data().line;
    const bool straight = (line >= 0 && n->curve().data().line == line) ||
                          CGAL::orientation(e->source()->point(), e->target()->point(),
                                            n->target()->point()) == CGAL::COLLINEAR;
    if (!straight)
      break;
    e = n;
  }
  return e->target()->point();
}

// Where the boundary shared by f and g ends, the union turns from one face's boundary into the
// other's. h is a halfedge of f whose twin lies in g. Two convex faces have a convex union
// exactly when it turns right at neither end of their shared boundary. A right turn is accepted
// when the corner lies within tol of the chord of its neighbouring corners (the block is then
// convex within tolerance, as check_convex_polygon measures it).
bool union_convex(Halfedge_handle h, Face_handle g, double tol) {
  const auto turn_ok = [tol](Halfedge_handle into, Halfedge_handle out) {
    const std::int32_t line = into->curve().data().line;
    if (line >= 0 && out->curve().data().line == line)
      return true;  // straight on
    const Point& q = into->target()->point();
    if (CGAL::orientation(into->source()->point(), q, out->target()->point()) != CGAL::RIGHT_TURN)
      return true;
    return deviation(run_start(into), q, run_end(out)) <= tol;
  };
  // The shared part starts at h->source(): f's boundary comes in, g's goes out.
  if (h->prev()->twin()->face() != g && !turn_ok(h->prev(), h->twin()->next()))
    return false;
  // It ends at h->target(): g's boundary comes in, f's goes out.
  if (h->next()->twin()->face() != g && !turn_ok(h->twin()->prev(), h->next()))
    return false;
  return true;
}

// The neighbour inside the domain to merge into, among those whose union with f is convex:
// same zones first, then the longest shared boundary, then the lower id (so that the result does
// not depend on the order edges are visited).
std::optional<Neighbour> best_neighbour(Face_handle f, double tol) {
  std::vector<Neighbour> candidates;
  for_each_boundary_halfedge(f, [&](Halfedge_handle h) {
    const Face_handle g = h->twin()->face();
    if (g == f || !g->data().inside)
      return;
    const double length = (to_vec2(h->target()->point()) - to_vec2(h->source()->point())).norm();
    auto it = std::find_if(candidates.begin(), candidates.end(),
                           [&](const Neighbour& n) { return n.face == g; });
    if (it == candidates.end())
      it = candidates.insert(it, {g, 0.0, g->data().zones == f->data().zones, true});
    it->shared_length += length;
    it->convex_union = it->convex_union && union_convex(h, g, tol);
  });
  std::optional<Neighbour> best;
  const auto rank = [](const Neighbour& n) {
    return std::make_tuple(n.same_zones, n.shared_length, -n.face->data().id);
  };
  for (const Neighbour& n : candidates) {
    if (n.convex_union && (!best || rank(n) > rank(*best)))
      best = n;
  }
  return best;
}

}  // namespace

SliverCounts merge_slivers(Arrangement& arr, double min_area, double tol) {
  SliverCounts counts;
  if (!(min_area > 0.0))
    return counts;
  std::vector<Face_handle> faces;  // by id; a merged-away face's entry is never read again
  std::vector<double> areas;
  std::vector<bool> alive;
  using Entry = std::pair<double, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> slivers;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->data().inside)
      continue;
    f->data().id = static_cast<int>(faces.size());
    faces.push_back(f);
    areas.push_back(face_area(f));
    alive.push_back(true);
    if (areas.back() < min_area)
      slivers.emplace(areas.back(), f->data().id);
  }
  while (!slivers.empty()) {
    const auto [a, id] = slivers.top();
    slivers.pop();
    if (!alive[id] || a != areas[id])
      continue;  // merged away, or queued again since
    const Face_handle f = faces[id];
    const std::optional<Neighbour> n = best_neighbour(f, tol);
    if (!n) {
      ++counts.kept;
      continue;
    }
    const FaceLabel keep = n->face->data();
    std::vector<Halfedge_handle> shared;
    for (const Halfedge_handle h : boundary_halfedges(f))
      if (h->twin()->face() == n->face)
        shared.push_back(h);
    Face_handle merged;
    for (const Halfedge_handle h : shared) {
      if (h->curve().data().trace >= 0)
        ++counts.joint_edges_removed;
      merged = arr.remove_edge(h);
    }
    merged->data() = keep;
    faces[keep.id] = merged;
    alive[id] = false;
    areas[keep.id] += areas[id];
    ++counts.merged;
    if (areas[keep.id] < min_area)
      slivers.emplace(areas[keep.id], keep.id);
  }
  return counts;
}

}  // namespace bimrock::cut
