#pragma once
/// @file Internal to the block cutter: every simple face inside the domain that is not convex
/// (a notch of the outline, a hole, a zone corner) is split into convex pieces by diagonals
/// between its corners, chosen by CGAL's optimal convex partition (Greene's dynamic programme,
/// O(n^4)) or, for faces with many corners, the Hertel-Mehlhorn approximation (at most 4 times
/// the optimal number of pieces). The diagonals become edges of the arrangement, tagged
/// `partition`, so the sliver merge and the extraction see convex faces only.
#include <bimrock/geometry/cut_arrangement.hpp>

namespace bimrock::cut {

/// Gives every face inside the domain its own region number (FaceLabel::region), in face order.
/// @return the number of regions
int number_regions(Arrangement& arr);

/// A convex partition of the simple counter-clockwise polygon `corners`: each piece as the
/// indices of its corners, counter-clockwise. Optimal up to `max_optimal_vertices` corners (and
/// wherever CGAL's optimal partition is a convex partition; else the approximation). Throws
/// GeometryError (item "domain") if neither is. (`corners` is not changed: CGAL's property map
/// of them wants a mutable vector.)
std::vector<std::vector<std::size_t>> convex_pieces(std::vector<Point>& corners,
                                                    int max_optimal_vertices);

/// Splits every face inside the domain with a corner reflex by more than `tol` (the distance
/// off the chord of its neighbouring corners; 0 splits every non-convex face); the pieces keep
/// the face's label (and region). @return the number of faces split
int partition_faces(Arrangement& arr, int max_optimal_vertices, double tol = 0.0);

}  // namespace bimrock::cut
