#pragma once
/// @file Finding where blocks touch: the shared edge segments (interfaces), the free boundary,
/// and overlaps. Candidate pairs come from CGAL's box intersection (O(n log^2 n + k)), so the
/// whole search is far from O(n^2).
#include <span>
#include <utility>
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {

/// A segment where edge `edge_i` of polygon i and edge `edge_j` of polygon j lie on each other.
/// The segment runs along edge_i in i's counter-clockwise sense; `normal` points from i into j.
struct SharedEdge {
  int i = 0;
  int j = 0;
  int edge_i = 0;
  int edge_j = 0;
  Segment segment;
  Vec2 normal;
};

/// Part of a polygon edge that no other polygon touches: the outline of the assembly.
struct BoundaryEdge {
  int polygon = 0;
  int edge = 0;
  Segment segment;
  Vec2 outward_normal;
};

/// Candidate pairs (i < j) whose bounding boxes, grown by tol, overlap.
std::vector<std::pair<int, int>> candidate_pairs(std::span<const Polygon> polygons, double tol);

/// Every shared edge segment longer than tol between the polygons (all convex, counter-clockwise).
/// Two edges share a segment when they are anti-parallel and within tol of each other's line;
/// a staggered joint, where one edge touches several neighbours, gives one segment per neighbour.
/// Sorted by (i, j, edge_i, position along the edge).
std::vector<SharedEdge> find_shared_edges(std::span<const Polygon> polygons, double tol);

/// The parts of every edge not covered by a shared edge (pieces shorter than tol dropped).
std::vector<BoundaryEdge> find_boundary_edges(std::span<const Polygon> polygons,
                                              std::span<const SharedEdge> shared, double tol);

/// For each point, the first polygon (the lowest index) that contains it within tol
/// (contains()), or -1 if none. Candidates by box intersection as above: O((n + m) log^2 + k),
/// not n x m.
std::vector<int> first_containing(std::span<const Polygon> polygons, std::span<const Vec2> points,
                                  double tol);

/// Pairs of convex polygons whose interiors overlap by more than tol (separating axis test).
std::vector<std::pair<int, int>> find_overlaps(std::span<const Polygon> polygons, double tol);

}  // namespace bimrock
