// Interface detection. Expected numbers are counted by hand on small patterns, and the outline
// length is the rectangle's perimeter (every edge is either shared by two blocks or boundary).
#include <gtest/gtest.h>

#include <bimrock/geometry/brick_pattern.hpp>
#include <bimrock/geometry/shared_edges.hpp>

namespace bimrock {
namespace {

double length_of(const std::vector<BoundaryEdge>& edges) {
  double l = 0.0;
  for (const auto& e : edges)
    l += e.segment.length();
  return l;
}

TEST(SharedEdges, GridOfThreeByTwoHasSevenInterfaces) {
  // 3 x 2 cells: 2 x 2 vertical joints + 3 horizontal joints.
  const auto blocks = brick_pattern(3, 2, 1.0, 1.0, Stagger::none);
  const auto shared = find_shared_edges(blocks, 1e-9);
  EXPECT_EQ(shared.size(), 7u);
  for (const SharedEdge& s : shared) {
    EXPECT_NEAR(s.segment.length(), 1.0, 1e-12);
    // The normal points from i into j: j's centroid lies on the normal's side.
    EXPECT_GT(s.normal.dot(centroid(blocks[s.j]) - centroid(blocks[s.i])), 0.0);
  }
  EXPECT_NEAR(length_of(find_boundary_edges(blocks, shared, 1e-9)), 10.0, 1e-12);
}

TEST(SharedEdges, StaggeredEdgeTouchesEachNeighbourOnce) {
  // Two rows of a brick wall, 2 bricks long: row 0 has 2 bricks, row 1 has 2 halves + 1 brick.
  // Vertical joints: 1 in row 0 + 2 in row 1; the bed joint is cut into 4 pieces at x = 0.5,
  // 1, 1.5.
  const auto blocks = brick_pattern(2, 2, 1.0, 1.0, Stagger::rows);
  ASSERT_EQ(blocks.size(), 5u);
  const auto shared = find_shared_edges(blocks, 1e-9);
  EXPECT_EQ(shared.size(), 7u);
  double bed = 0.0;
  for (const SharedEdge& s : shared)
    if (std::abs(s.normal.y()) > 0.5)
      bed += s.segment.length();
  EXPECT_NEAR(bed, 2.0, 1e-12);
  EXPECT_NEAR(length_of(find_boundary_edges(blocks, shared, 1e-9)), 8.0, 1e-12);
}

TEST(SharedEdges, BlocksTouchingAtACornerOnlyShareNothing) {
  const std::vector<Polygon> blocks{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                                    {{{1, 1}, {2, 1}, {2, 2}, {1, 2}}}};
  EXPECT_TRUE(find_shared_edges(blocks, 1e-9).empty());
}

TEST(SharedEdges, SeparatedByMoreThanTheToleranceIsNoInterface) {
  const std::vector<Polygon> blocks{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                                    {{{1 + 1e-6, 0}, {2, 0}, {2, 1}, {1 + 1e-6, 1}}}};
  EXPECT_TRUE(find_shared_edges(blocks, 1e-9).empty());
  EXPECT_EQ(find_shared_edges(blocks, 1e-5).size(), 1u);
}

TEST(Overlaps, FoundBetweenOverlappingBlocksOnly) {
  const std::vector<Polygon> blocks{{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                                    {{{1, 0}, {2, 0}, {2, 1}, {1, 1}}},
                                    {{{1.5, 0.5}, {2.5, 0.5}, {2.5, 1.5}, {1.5, 1.5}}}};
  const auto overlaps = find_overlaps(blocks, 1e-9);
  ASSERT_EQ(overlaps.size(), 1u);
  EXPECT_EQ(overlaps[0], std::make_pair(1, 2));
}

TEST(SharedEdges, CandidatePairsGrowLinearlyOnAGrid) {
  // Each cell of a grid has at most 8 neighbours whose boxes touch it: pairs <= 4 n.
  const auto blocks = brick_pattern(40, 40, 1.0, 1.0, Stagger::none);
  const auto pairs = candidate_pairs(blocks, 1e-9);
  EXPECT_EQ(pairs.size(), 2u * 39 * 40 + 2u * 39 * 39);
}

// The first polygon holding each point, against a search of every polygon in order (what the
// model builder did per point): points inside bricks, on their edges and corners (held by 2-4
// bricks, the first of which wins), within tol outside the wall and beyond it.
TEST(PointLocation, FirstContainingAgreesWithASearchOfEveryPolygon) {
  const auto blocks = brick_pattern(12, 9, 1.0, 0.5, Stagger::rows);
  const double tol = 1e-9;
  std::vector<Vec2> points;
  for (int i = -2; i <= 50; ++i) {
    for (int j = -2; j <= 38; ++j)
      points.push_back({0.25 * i, 0.125 * j});  // a lattice through edges and corners
  }
  points.push_back({12.0 + 0.5 * tol, 1.0});  // within tol of the right side
  points.push_back({12.0 + 2.0 * tol, 1.0});  // beyond it
  const std::vector<int> first = first_containing(blocks, points, tol);
  ASSERT_EQ(first.size(), points.size());
  int inside = 0;
  int shared = 0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    int expected = -1;
    int holders = 0;
    for (std::size_t b = 0; b < blocks.size(); ++b) {
      if (contains(blocks[b], points[k], tol)) {
        expected = expected < 0 ? static_cast<int>(b) : expected;
        ++holders;
      }
    }
    EXPECT_EQ(first[k], expected) << points[k].transpose();
    inside += expected >= 0 ? 1 : 0;
    shared += holders > 1 ? 1 : 0;
  }
  EXPECT_GT(shared, 300);  // the lattice does test points held by several bricks
  EXPECT_LT(inside, static_cast<int>(points.size()));  // and points held by none
  EXPECT_EQ(first[points.size() - 2],
            first_containing(blocks, std::vector<Vec2>{{11.9, 1.0}}, tol)[0]);
  EXPECT_EQ(first.back(), -1);
}

}  // namespace
}  // namespace bimrock
