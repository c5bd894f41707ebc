#pragma once
/// @file Internal to the block cutter: straight cuts through intact rock that turn every face
/// inside the domain into a simple polygon (one boundary cycle visiting each vertex once), the
/// form a convex partition needs.
///  - A trace that ends inside rock leaves a dangling edge (an antenna); it is extended along
///    its own direction to the first edge it meets, the "fictitious joint" of UDEC, so the joint
///    becomes an interface between two blocks and the rest of the line a rock bridge.
///  - A hole that no trace reaches (an inner boundary cycle), or a cycle attached to the outer
///    one at a single vertex, is joined by vertical cuts from its top and bottom vertices.
#include <bimrock/geometry/cut_arrangement.hpp>

namespace bimrock::cut {

/// Inserts the segment from h->target() along `dir` to the first point where it meets the
/// boundary of h->face(), splitting the edge hit there. `dir` must point into the face between
/// h and h->next(). Both faces of the new edge take the label of the face that was cut.
/// @param line the input line the cut continues (CurveTag::line), or -1
/// @return the new halfedge, directed away from h->target()
Halfedge_handle cut_along_ray(Arrangement& arr, Halfedge_handle h, const Kernel::Vector_2& dir,
                              std::int32_t line = -1);

/// Extends every dangling trace end inside the domain. @return the number of extensions
int extend_dangling_ends(Arrangement& arr);

/// Cuts every face inside the domain until it is simple. @return the number of cuts
int make_faces_simple(Arrangement& arr);

}  // namespace bimrock::cut
