// The zones K is condensed onto (grow_zone): rings of neighbours around the flagged blocks until
// the target. The expected counts are those of rings on a grid of square blocks, where a block's
// neighbours are the four that share an edge with it: the blocks at grid distance k from one
// block are 4k, and from a 3 x 3 square 12 + 4 (k - 1).
#include <cmath>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/model/model.hpp>
#include <bimrock/solve/condensed_stiffness.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr int kGridSide = 40;

Model grid_model() {
  CaseSpec c;
  c.file = "case.yaml";
  c.block_materials = {testing::rock(10e9, 0.2)};
  c.joint_materials = {testing::springs("joint", 1e10, 1e10)};
  c.blocks = testing::blocks_of(brick_pattern(kGridSide, kGridSide, 1.0, 1.0, Stagger::none));
  c.default_joint = "joint";
  return build_model(c);
}

// The block whose centroid is the middle of grid cell (x, y).
int at(const Model& m, int x, int y) {
  for (int b = 0; b < m.n_blocks(); ++b) {
    const Vec2 c = m.blocks[static_cast<std::size_t>(b)].centroid;
    if (std::abs(c.x() - (x + 0.5)) < 1e-9 && std::abs(c.y() - (y + 0.5)) < 1e-9)
      return b;
  }
  ADD_FAILURE() << "no block at " << x << ", " << y;
  return 0;
}

// Flagged blocks within grid distance `reach` of cell (x, y).
int near(const Model& m, const std::vector<char>& zone, int x, int y, int reach) {
  int count = 0;
  for (int j = 0; j < kGridSide; ++j)
    for (int i = 0; i < kGridSide; ++i)
      if (std::abs(i - x) + std::abs(j - y) <= reach && zone[static_cast<std::size_t>(at(m, i, j))])
        ++count;
  return count;
}

// One block and a 3 x 3 square far apart, grown together ring by ring to a target of 200:
// after 5 rings 61 + 109 = 170 blocks, after 6 rings 85 + 141 = 226.
TEST(GrowZone, RingsAroundEveryFlaggedBlockUntilTheTarget) {
  const Model m = grid_model();
  std::vector<char> zone(static_cast<std::size_t>(m.n_blocks()), 0);
  zone[static_cast<std::size_t>(at(m, 7, 7))] = 1;
  for (int y = 24; y <= 26; ++y)
    for (int x = 24; x <= 26; ++x)
      zone[static_cast<std::size_t>(at(m, x, y))] = 1;
  const std::vector<char> grown = grow_zone(m, zone, 200);
  for (std::size_t b = 0; b < zone.size(); ++b) {
    if (zone[b]) {
      EXPECT_TRUE(grown[b]) << "a flagged block left out: " << b;
    }
  }
  EXPECT_EQ(near(m, grown, 7, 7, 6), 85);
  EXPECT_EQ(near(m, grown, 25, 25, 8), 141);
  int total = 0;
  for (char g : grown)
    total += g;
  EXPECT_EQ(total, 85 + 141);
}

// Two blocks one apart grown to 10: the first ring adds the 7 blocks at grid distance 1 from
// either (the one between them once), 9 in all; the second, which passes the target, is added
// whole: the 12 at distance 2, 21 in all.
TEST(GrowZone, TheLastRingIsAddedWhole) {
  const Model m = grid_model();
  std::vector<char> zone(static_cast<std::size_t>(m.n_blocks()), 0);
  zone[static_cast<std::size_t>(at(m, 14, 15))] = 1;
  zone[static_cast<std::size_t>(at(m, 16, 15))] = 1;
  const std::vector<char> grown = grow_zone(m, zone, 10);
  int total = 0;
  for (char g : grown)
    total += g;
  EXPECT_EQ(total, 21);
}

// With `within`, a block hemmed in by blocks it does not flag takes no ring; the others grow
// until the target: the single block at (15, 15) takes 7 rings (113 blocks, 85 after 6), 114
// in all.
TEST(GrowZone, OnlyBlocksWithinAreAdded) {
  const Model m = grid_model();
  std::vector<char> zone(static_cast<std::size_t>(m.n_blocks()), 0);
  std::vector<char> within(zone.size(), 1);
  zone[static_cast<std::size_t>(at(m, 3, 3))] = 1;
  for (const auto& [x, y] : {std::pair{2, 3}, {4, 3}, {3, 2}, {3, 4}})
    within[static_cast<std::size_t>(at(m, x, y))] = 0;
  zone[static_cast<std::size_t>(at(m, 15, 15))] = 1;
  const std::vector<char> grown = grow_zone(m, zone, 100, &within);
  int total = 0;
  for (char g : grown)
    total += g;
  EXPECT_EQ(total, 114);
  EXPECT_EQ(near(m, grown, 3, 3, 6), 1);
}

// With a ring limit, the growth stops there whatever the target: a single block and its first
// two rings, 2 r^2 + 2 r + 1 = 13 blocks for r = 2 (as the counts above: 85 after 6 rings).
TEST(GrowZone, StopsAfterTheRingsAsked) {
  const Model m = grid_model();
  std::vector<char> zone(static_cast<std::size_t>(m.n_blocks()), 0);
  zone[static_cast<std::size_t>(at(m, 15, 15))] = 1;
  const std::vector<char> grown = grow_zone(m, zone, m.n_blocks(), nullptr, 2);
  int total = 0;
  for (char g : grown)
    total += g;
  EXPECT_EQ(total, 13);
  EXPECT_EQ(near(m, grown, 15, 15, 2), 13);
}

}  // namespace
}  // namespace bimrock
