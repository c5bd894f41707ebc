// Voronoi subdivision of large blocks. Cell counts are hand counts of the seeds (a jittered
// grid of 5 x 5 cells of 2 m on a 10 m square keeps every seed in its own grid cell, inside the
// block); areas are the parents' closed-form areas.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>

#include <bimrock/geometry/brick_pattern.hpp>
#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/voronoi_subdivision.hpp>

#include "block_checks.hpp"

namespace bimrock {
namespace {

const Polygon kSquare{{{0, 0}, {10, 0}, {10, 10}, {0, 10}}};

std::vector<Polygon> polygons(const std::vector<VoronoiCell>& cells) {
  std::vector<Polygon> p;
  for (const VoronoiCell& c : cells)
    p.push_back(c.polygon);
  return p;
}

TEST(VoronoiSubdivision, JitteredGridGivesOneConvexCellPerSeed) {
  const auto cells = voronoi_subdivision(kSquare, 7, {.target_size = 2.0, .seed = 1});
  EXPECT_EQ(cells.size(), 25u);
  for (const VoronoiCell& c : cells)
    EXPECT_EQ(c.parent, 7);
  const auto p = polygons(cells);
  EXPECT_NEAR(test::total_area(p), 100.0, 1e-12 * 100.0);
  test::expect_convex_ccw(p, 1e-8);
  test::expect_no_overlap_beyond(p, 1e-8);
}

TEST(VoronoiSubdivision, RandomSeedsGiveAreaOverTargetSquaredCells) {
  // round(100 / 2^2) = 25 seeds, uniform in the square.
  const auto cells = voronoi_subdivision(
      kSquare, 0,
      {.target_size = 2.0, .pattern = SeedPattern::random, .seed = 4, .min_cell_fraction = 0.0});
  EXPECT_EQ(cells.size(), 25u);
  EXPECT_NEAR(test::total_area(polygons(cells)), 100.0, 1e-12 * 100.0);
  test::expect_convex_ccw(polygons(cells), 1e-8);
}

TEST(VoronoiSubdivision, SameSeedSameCellsOtherSeedOtherCells) {
  const auto bytes = [](const std::vector<VoronoiCell>& cells) {
    std::vector<double> v;
    for (const VoronoiCell& c : cells)
      for (const Vec2& p : c.polygon.vertices)
        v.insert(v.end(), {p.x(), p.y()});
    return v;
  };
  const VoronoiOptions o{.target_size = 1.5, .seed = 9};
  const VoronoiOptions other{.target_size = 1.5, .seed = 10};
  EXPECT_EQ(bytes(voronoi_subdivision(kSquare, 0, o)), bytes(voronoi_subdivision(kSquare, 0, o)));
  EXPECT_NE(bytes(voronoi_subdivision(kSquare, 0, o)),
            bytes(voronoi_subdivision(kSquare, 0, other)));
}

TEST(VoronoiSubdivision, SmallBlockComesBackWhole) {
  const Polygon small{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}};
  const auto cells = voronoi_subdivision(small, 3, {.target_size = 2.0});
  ASSERT_EQ(cells.size(), 1u);
  EXPECT_EQ(cells[0].polygon.vertices, small.vertices);
  EXPECT_EQ(cells[0].parent, 3);
}

TEST(VoronoiSubdivision, OnlyLargeBlocksAreSplitAndEachKeepsItsArea) {
  // A brick wall of 4 x 2 m bricks (area 8) and 2 x 2 m halves (area 4): with max_area 5 only
  // the 5 whole bricks of brick_pattern(2, 3, 4, 2, rows) are split (rows 0, 2: 2 bricks; row
  // 1: 1 brick + 2 halves).
  const auto blocks = brick_pattern(2, 3, 4.0, 2.0, Stagger::rows);
  const auto cells = subdivide_large_blocks(blocks, 5.0, {.target_size = 1.0, .seed = 2});
  std::map<int, double> area;
  std::map<int, int> count;
  for (const VoronoiCell& c : cells) {
    area[c.parent] += signed_area(c.polygon);
    ++count[c.parent];
  }
  ASSERT_EQ(area.size(), blocks.size());
  int split = 0;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const int parent = static_cast<int>(k);
    EXPECT_NEAR(area[parent], signed_area(blocks[k]), 1e-12 * 8.0);
    split += count[parent] > 1 ? 1 : 0;
  }
  EXPECT_EQ(split, 5);
  test::expect_convex_ccw(polygons(cells), 1e-8);
}

TEST(VoronoiSubdivision, ASliverOfSmallAreaIsCutAcrossIntoShortPieces) {
  // The triangle (0, 0), (10, 0), (10, 0.05): area 0.25, under max_area 2 h^2 = 0.5 (h = 0.5),
  // but 10 m long, as the partition of a rock mass round a circular opening fans thin triangles
  // across the whole domain. It holds no grid seed, so it is cut across its length into 10 / 0.5
  // = 20 pieces; the one at the tip, 0.25 (0.5 / 10)^2 = 0.000625 m^2, is under the smallest
  // cell kept (0.01 h^2 = 0.0025 m^2) and joins its neighbour (together 0.0025 m^2, kept): 19
  // pieces, each convex, none longer than 2 sqrt(max_area), the area kept.
  const Polygon sliver{{{0, 0}, {10, 0}, {10, 0.05}}};
  const std::vector<Polygon> blocks{sliver};
  const auto cells = subdivide_large_blocks(blocks, 0.5, {.target_size = 0.5, .seed = 4});
  EXPECT_EQ(cells.size(), 19u);
  double area = 0.0;
  for (const VoronoiCell& c : cells) {
    area += signed_area(c.polygon);
    double longest = 0.0;
    for (const Vec2& a : c.polygon.vertices)
      for (const Vec2& b : c.polygon.vertices)
        longest = std::max(longest, (b - a).norm());
    EXPECT_LE(longest, 2.0 * std::sqrt(0.5));
  }
  EXPECT_NEAR(area, 0.25, 1e-12);
  test::expect_convex_ccw(polygons(cells), 1e-10);
}

TEST(VoronoiSubdivision, BadOptionsAndBlocksAreNamed) {
  try {
    voronoi_subdivision(kSquare, 0, {.target_size = 0.0});
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.item(), "voronoi.target_size");
  }
  try {
    voronoi_subdivision({{{0, 0}, {0, 10}, {10, 10}, {10, 0}}}, 4, {});  // clockwise
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_EQ(e.item(), "blocks[4]");
  }
}

}  // namespace
}  // namespace bimrock
