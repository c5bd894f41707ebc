#pragma once
/// @file Internal to the block cutter: faces too small to be useful blocks (slivers, where two
/// joints nearly meet a third one or an outline, or a partition cuts a corner) are merged into a
/// neighbour instead of being dropped, so the blocks still tile the domain exactly.
#include <bimrock/geometry/cut_arrangement.hpp>

namespace bimrock::cut {

struct SliverCounts {
  int merged = 0;               ///< slivers merged into a neighbour
  int kept = 0;                 ///< slivers with no neighbour to merge into convexly (kept)
  int joint_edges_removed = 0;  ///< edges on a joint trace that disappeared in a merge
};

/// Merges every face inside the domain with area below min_area into a neighbour such that the
/// union is still convex (every face is convex by now) within `tol`: a corner of the union may
/// turn right by less than tol, as where a sliver of width 1e-15 between two nearly parallel
/// joints meets a third line. Same zones first, then the longest
/// shared boundary; smallest slivers first, and a merged face that is still too small is merged
/// again. A sliver with no such neighbour is kept and counted. The merged face keeps the
/// neighbour's label, and the shared edges are removed (a joint piece between them becomes
/// intact rock).
SliverCounts merge_slivers(Arrangement& arr, double min_area, double tol);

}  // namespace bimrock::cut
