#include <bimrock/geometry/convex_partition.hpp>

#include <algorithm>
#include <iterator>
#include <string>
#include <utility>

#include <CGAL/Partition_traits_2.h>
#include <CGAL/exceptions.h>
#include <CGAL/partition_2.h>
#include <CGAL/partition_is_valid_2.h>
#include <CGAL/property_map.h>

#include <bimrock/geometry/geometry_error.hpp>

namespace bimrock::cut {
namespace {

// Partition on corner indices: the pieces come back as index lists, so no exact point is ever
// compared for equality (which would force exact arithmetic) to find which corner it is.
using PointMap = CGAL::Pointer_property_map<Point>::type;
using PartitionTraits = CGAL::Partition_traits_2<Kernel, PointMap>;

// Diagonals (pairs of corner indices, lower first) of a convex partition of the corners.
std::vector<std::pair<std::size_t, std::size_t>> diagonals(std::vector<Point>& corners,
                                                           int max_optimal_vertices) {
  const std::size_t m = corners.size();
  std::vector<std::pair<std::size_t, std::size_t>> out;
  for (const std::vector<std::size_t>& ring : convex_pieces(corners, max_optimal_vertices)) {
    for (std::size_t k = 0; k < ring.size(); ++k) {
      const std::size_t u = ring[k];
      const std::size_t w = ring[(k + 1) % ring.size()];
      if (w != (u + 1) % m && u != (w + 1) % m)
        out.push_back(std::minmax(u, w));
    }
  }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace

std::vector<std::vector<std::size_t>> convex_pieces(std::vector<Point>& corners,
                                                    int max_optimal_vertices) {
  const std::size_t m = corners.size();
  std::vector<std::size_t> index(m);
  for (std::size_t k = 0; k < m; ++k)
    index[k] = k;
  const PartitionTraits traits(CGAL::make_property_map(corners));
  std::vector<PartitionTraits::Polygon_2> pieces;
  // A guard around a bug of CGAL's optimal convex partition (5.5, open upstream): on some faces,
  // e.g. one with three nearly collinear corners beside a notched hole, it returns a piece with
  // reflex corners. CGAL checks its result only in debug builds (a postcondition, which throws
  // there); in release nothing does. Checked here in every build: a partition that is not convex,
  // or that CGAL refuses, is replaced by the approximation's, which holds.
  const auto partition = [&](auto&& partition_2) {
    pieces.clear();
    try {
      partition_2(index.begin(), index.end(), std::back_inserter(pieces), traits);
    } catch (const CGAL::Failure_exception&) {
      pieces.clear();
      return false;
    }
    return CGAL::convex_partition_is_valid_2(index.begin(), index.end(), pieces.begin(),
                                             pieces.end(), traits);
  };
  const auto optimal = [](auto... args) { CGAL::optimal_convex_partition_2(args...); };
  const auto approximate = [](auto... args) { CGAL::approx_convex_partition_2(args...); };
  const bool small = m <= static_cast<std::size_t>(max_optimal_vertices);
  if (!(small && partition(optimal)) && !partition(approximate)) {
    const Vec2 at = to_vec2(corners.front());
    throw GeometryError("domain", "a face of the cut blocks near (" + std::to_string(at.x()) +
                                      ", " + std::to_string(at.y()) +
                                      ") could not be split into convex blocks; move a joint "
                                      "or the outline there a little");
  }
  std::vector<std::vector<std::size_t>> out;
  out.reserve(pieces.size());
  for (const auto& piece : pieces)
    out.emplace_back(piece.vertices_begin(), piece.vertices_end());
  return out;
}

int number_regions(Arrangement& arr) {
  int region = 0;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f)
    if (f->data().inside)
      f->data().region = region++;
  return region;
}

int partition_faces(Arrangement& arr, int max_optimal_vertices, double tol) {
  std::vector<Face_handle> faces;
  FaceCorners fc;
  for (auto f = arr.faces_begin(); f != arr.faces_end(); ++f) {
    if (!f->data().inside)
      continue;
    find_corners(f, fc);
    if (!fc.convex && (tol == 0.0 || fc.reflex_deviation > tol))
      faces.push_back(f);
  }
  for (const Face_handle f : faces) {  // pieces are new faces: the list stays valid
    find_corners(f, fc);
    const FaceLabel label = f->data();
    std::vector<Point> corners;
    std::vector<Vertex_handle> vertices;
    for (std::size_t i : fc.corner_pos) {
      corners.push_back(fc.cycle[i]->source()->point());
      vertices.push_back(fc.cycle[i]->source());
    }
    for (const auto& [u, w] : diagonals(corners, max_optimal_vertices)) {
      const Traits::X_monotone_curve_2 cut(Traits::Base_x_monotone_curve_2(corners[u], corners[w]),
                                           CurveTag{.partition = true});
      const Halfedge_handle e = arr.insert_at_vertices(cut, vertices[u], vertices[w]);
      e->face()->data() = label;
      e->twin()->face()->data() = label;
    }
  }
  return static_cast<int>(faces.size());
}

}  // namespace bimrock::cut
