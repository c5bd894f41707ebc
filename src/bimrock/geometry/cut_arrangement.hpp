#pragma once
/// @file Internal to the block cutter (not part of the public API): the CGAL arrangement in
/// which the domain outline, holes, zone outlines and joint traces are overlaid, with exact
/// constructions so every intersection point is exact and every predicate is decided right.
/// Each edge carries a CurveTag (what it lies on), each face a FaceLabel (inside the domain?
/// which zones?), each vertex and halfedge an int scratch/index field.
#include <cstdint>
#include <span>
#include <vector>

#include <CGAL/Arr_curve_data_traits_2.h>
#include <CGAL/Arr_extended_dcel.h>
#include <CGAL/Arr_segment_traits_2.h>
#include <CGAL/Arrangement_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include <bimrock/geometry/domain.hpp>
#include <bimrock/geometry/joint_set.hpp>

namespace bimrock::cut {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using Point = Kernel::Point_2;

/// What an arrangement edge lies on. Where input curves overlap, their tags merge: the parity
/// fields by XOR (crossing two coincident outlines changes nothing), the trace by the lowest
/// index, the rock-bridge flag by OR.
struct CurveTag {
  std::uint64_t zones = 0;  ///< bit z: on the outline of zone z (odd number of times)
  std::int32_t trace = -1;  ///< lowest index of a joint trace it lies on, -1 for none
  /// Lowest index of an input segment (outline, hole and zone edges, then traces) it lies on; a
  /// rock bridge extending a trace takes the trace's. Two edges with the same line are
  /// collinear, known without an orientation test (which is degenerate, hence exact and slow,
  /// exactly when they are).
  std::int32_t line = -1;
  bool boundary = false;     ///< on the domain outline or a hole (odd number of times)
  bool rock_bridge = false;  ///< a cut the cutter added through intact rock
  bool partition = false;    ///< a diagonal splitting a non-convex region into convex pieces
  friend bool operator==(const CurveTag&, const CurveTag&) = default;
};

struct MergeTags {
  CurveTag operator()(const CurveTag& a, const CurveTag& b) const;
};

/// Where a face lies. Found once by crossing edges from the unbounded face; faces created
/// later by splitting copy the label of the face they were split from.
struct FaceLabel {
  bool known = false;
  bool inside = false;      ///< inside the outline and outside every hole
  std::uint64_t zones = 0;  ///< the zones containing it
  int region = -1;          ///< the region (face before the convex partition) it is part of
  int id = -1;              ///< scratch index used by the sliver merge
};

using Traits =
    CGAL::Arr_curve_data_traits_2<CGAL::Arr_segment_traits_2<Kernel>, CurveTag, MergeTags>;
using Dcel = CGAL::Arr_extended_dcel<Traits, int, int, FaceLabel>;
using Arrangement = CGAL::Arrangement_2<Traits, Dcel>;
using Face_handle = Arrangement::Face_handle;
using Halfedge_handle = Arrangement::Halfedge_handle;
using Vertex_handle = Arrangement::Vertex_handle;

/// Inserts every outline, hole, zone outline and trace at once (one sweep: O((n + k) log n) for
/// n segments and k crossings), then labels every face. Zero-length traces are skipped.
void build(Arrangement& arr, const Domain& domain, std::span<const JointTrace> traces);

/// Labels every face by crossing edges from the unbounded face (breadth first).
void label_faces(Arrangement& arr);

/// The first zone of a zone mask, or -1.
int first_zone(std::uint64_t zones);

/// Double coordinates of an exact point (the midpoint of its interval approximation, within
/// an ulp or two of the exact value).
Vec2 to_vec2(const Point& p);

/// Area of a face: its outer boundary less its holes, in doubles.
double face_area(Face_handle f);

/// Calls fn(h) for every halfedge h of every boundary cycle of f (outer and inner), f on its left.
template <typename Fn>
void for_each_boundary_halfedge(Face_handle f, Fn&& fn) {
  const auto walk = [&](Arrangement::Ccb_halfedge_circulator first) {
    auto c = first;
    do {
      fn(Halfedge_handle(c));
    } while (++c != first);
  };
  for (auto o = f->outer_ccbs_begin(); o != f->outer_ccbs_end(); ++o)
    walk(*o);
  for (auto i = f->inner_ccbs_begin(); i != f->inner_ccbs_end(); ++i)
    walk(*i);
}

/// The same halfedges as a list (where the arrangement changes while they are used).
std::vector<Halfedge_handle> boundary_halfedges(Face_handle f);

/// The outer boundary cycle of a simple face and its corners, the vertices where it turns.
struct FaceCorners {
  std::vector<Halfedge_handle> cycle;   ///< in order, f on the left
  std::vector<std::size_t> corner_pos;  ///< position in cycle of the halfedge leaving a corner
  bool convex = true;                   ///< no corner turns right
  /// The largest distance by which a corner turning right lies off the chord of its neighbouring
  /// corners (0 when convex): a sliver merge may leave corners reflex by less than a tolerance.
  double reflex_deviation = 0.0;
  std::vector<bool> turns_right;  ///< per corner
};

/// How far a corner p -> q -> r turning right is from straight: the distance of q from the line
/// through p and r (doubles), or infinity when it turns back by more than 90 degrees.
double deviation(const Point& p, const Point& q, const Point& r);

/// Fills `out` (reused to save allocations). Collinearity is decided from CurveTag::line where
/// possible, else by the exact orientation predicate.
void find_corners(Face_handle f, FaceCorners& out);

}  // namespace bimrock::cut
