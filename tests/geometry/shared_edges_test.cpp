// Interface detection. Expected numbers are counted by hand on small patterns, and the outline
// length is the rectangle's perimeter (every edge is either shared by two blocks or boundary).
#include <cmath>

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

// Two half discs of 3 001 vertices each (9e6 edge pairs: the search by edge boxes and hulls):
// they share their diameter only, its outline is the two arcs (2 n chords of 2 R sin(pi / 2n)),
// and they overlap once one is moved a millimetre into the other, not when moved away.
TEST(SharedEdges, TwoHalfDiscsOfManyVerticesShareTheirDiameterOnly) {
  const int n = 3000;
  const double r = 100.0;
  const auto half = [&](double start, double dy) {
    Polygon p;
    for (int k = 0; k <= n; ++k) {
      const double a = start + M_PI * k / n;
      p.vertices.push_back({r * std::cos(a), r * std::sin(a) + dy});
    }
    return p;
  };
  const double tol = 1e-9 * 2.0 * std::sqrt(2.0) * r;
  const std::vector<Polygon> discs{half(0.0, 0.0), half(M_PI, 0.0)};
  const auto shared = find_shared_edges(discs, tol);
  ASSERT_EQ(shared.size(), 1u);
  EXPECT_EQ(shared[0].edge_i, n);  // the closing edges, from (-r, 0) and from (r, 0)
  EXPECT_EQ(shared[0].edge_j, n);
  EXPECT_NEAR(shared[0].segment.length(), 2.0 * r, 1e-9);
  EXPECT_NEAR(length_of(find_boundary_edges(discs, shared, tol)),
              2.0 * n * 2.0 * r * std::sin(M_PI / (2.0 * n)), 1e-9);
  EXPECT_TRUE(find_overlaps(discs, tol).empty());

  const std::vector<Polygon> into{half(0.0, 0.0), half(M_PI, 1e-3)};
  EXPECT_EQ(find_overlaps(into, tol), (std::vector<std::pair<int, int>>{{0, 1}}));
  EXPECT_TRUE(find_shared_edges(into, tol).empty());
  const std::vector<Polygon> apart{half(0.0, 0.0), half(M_PI, -1e-3)};
  EXPECT_TRUE(find_overlaps(apart, tol).empty());
  EXPECT_TRUE(find_shared_edges(apart, tol).empty());
}

// A small block against a large one (4 x 5 000 edge pairs, the large polygons' search): on its
// side, sharing part of it; overlapping it; a corner a millimetre inside it.
TEST(SharedEdges, ASmallBlockBesideALargeOneIsFoundByTheLargeSearch) {
  Polygon big;  // a square of side 10, 1 250 vertices on each side, counter-clockwise
  for (int k = 0; k < 1250; ++k)
    big.vertices.push_back({10.0 * k / 1250.0, 0.0});
  for (int k = 0; k < 1250; ++k)
    big.vertices.push_back({10.0, 10.0 * k / 1250.0});
  for (int k = 0; k < 1250; ++k)
    big.vertices.push_back({10.0 - 10.0 * k / 1250.0, 10.0});
  for (int k = 0; k < 1250; ++k)
    big.vertices.push_back({0.0, 10.0 - 10.0 * k / 1250.0});
  const double tol = 1e-9 * std::sqrt(200.0);
  const Polygon beside{{{10, 3}, {12, 3}, {12, 5.5}, {10, 5.5}}};
  const std::vector<Polygon> touching{big, beside};
  double length = 0.0;
  for (const SharedEdge& e : find_shared_edges(touching, tol))
    length += e.segment.length();
  EXPECT_NEAR(length, 2.5, 1e-9);  // from y = 3 to 5.5, in pieces of 10 / 1250 m
  EXPECT_TRUE(find_overlaps(touching, tol).empty());
  const Polygon inside{{{9.999, 3}, {12, 3}, {12, 5.5}, {9.999, 5.5}}};
  EXPECT_EQ(find_overlaps(std::vector<Polygon>{big, inside}, tol).size(), 1u);
}

}  // namespace
}  // namespace bimrock
