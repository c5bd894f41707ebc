#pragma once
// Checks shared by the block-generation tests: a set of blocks tiles a domain when every block
// is a valid convex polygon, no two overlap, and their areas add up to the domain's.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <bimrock/geometry/block_cutter.hpp>
#include <bimrock/geometry/shared_edges.hpp>

namespace bimrock::test {

inline double total_area(const std::vector<Polygon>& blocks) {
  double a = 0.0;
  for (const Polygon& p : blocks)
    a += signed_area(p);
  return a;
}

inline void expect_convex_ccw(const std::vector<Polygon>& blocks, double tol) {
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const PolygonCheck c = check_convex_polygon(blocks[k], tol);
    EXPECT_EQ(c.defect, PolygonDefect::none) << "block " << k << ": " << describe(c);
  }
}

// Exact separating-axis test on the given doubles (exact predicates): two convex polygons have
// disjoint interiors iff the line of some edge of one has the other on its closed outer side.
inline bool interiors_overlap(const Polygon& a, const Polygon& b) {
  using K = CGAL::Exact_predicates_inexact_constructions_kernel;
  const auto separates = [](const Polygon& p, const Polygon& q) {
    for (std::size_t k = 0; k < p.size(); ++k) {
      const Segment e = p.edge(k);
      const K::Point_2 ea(e.a.x(), e.a.y());
      const K::Point_2 eb(e.b.x(), e.b.y());
      const bool all_outside = std::none_of(q.vertices.begin(), q.vertices.end(), [&](auto& v) {
        return CGAL::orientation(ea, eb, K::Point_2(v.x(), v.y())) == CGAL::LEFT_TURN;
      });
      if (all_outside)
        return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

// Blocks whose vertices are exactly representable (no rounded crossing points) must not overlap
// at all, checked exactly.
inline void expect_no_overlap_exact(const std::vector<Polygon>& blocks) {
  for (const auto& [i, j] : candidate_pairs(blocks, 0.0))
    EXPECT_FALSE(interiors_overlap(blocks[i], blocks[j])) << "blocks " << i << " and " << j;
}

// Where crossing points were rounded to doubles, a T-junction may sit an ulp inside its
// neighbour's side: overlaps are allowed only within the model tolerance.
inline void expect_no_overlap_beyond(const std::vector<Polygon>& blocks, double tol) {
  EXPECT_TRUE(find_overlaps(blocks, tol).empty());
}

// The byte-level image of a cut, to compare two runs.
inline std::vector<unsigned char> bytes_of(const BlockCut& cut) {
  std::vector<unsigned char> out(cut.vertices.size() * sizeof(Vec2));
  if (!out.empty())
    std::memcpy(out.data(), cut.vertices.data(), out.size());
  for (const CutBlock& b : cut.blocks) {
    const auto* p = reinterpret_cast<const unsigned char*>(b.vertex_ids.data());
    out.insert(out.end(), p, p + b.vertex_ids.size() * sizeof(int));
  }
  return out;
}

}  // namespace bimrock::test
