// The zones K is condensed onto (grow_zone): rings of neighbours around the flagged blocks, each
// island of them grown to its share of the target. The expected counts are those of rings on a
// grid of square blocks, where a block's neighbours are the four that share an edge with it: the
// blocks at grid distance k from one block are 4k, and from a 3 x 3 square 12 + 4 (k - 1).
#include <cmath>
#include <cstdlib>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/condensed_stiffness.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr int kSide = 30;

Model grid() {
  CaseSpec c;
  c.file = "case.yaml";
  c.block_materials = {testing::rock(10e9, 0.2)};
  c.joint_materials = {testing::springs("joint", 1e10, 1e10)};
  c.blocks = testing::blocks_of(brick_pattern(kSide, kSide, 1.0, 1.0, Stagger::none));
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
  for (int j = 0; j < kSide; ++j)
    for (int i = 0; i < kSide; ++i)
      if (std::abs(i - x) + std::abs(j - y) <= reach && zone[static_cast<std::size_t>(at(m, i, j))])
        ++count;
  return count;
}

// One block near a corner and a 3 x 3 square in the middle: 1 and 9 of 10 flagged blocks, so
// shares of 20 and 180 of a target of 200. The single block takes rings until it has 20
// (1 + 4 + 8 + 12 = 25), the square until it has 180 (9 + 12 + 16 + ... + 40 = 217). Grown
// together ring by ring, as zones were before, the single block would have taken 6 rings (85
// blocks) for the square's 141.
TEST(GrowZone, EachIslandGrowsToItsShareOfTheTarget) {
  const Model m = grid();
  std::vector<char> zone(static_cast<std::size_t>(m.n_blocks()), 0);
  zone[static_cast<std::size_t>(at(m, 3, 3))] = 1;
  for (int y = 14; y <= 16; ++y)
    for (int x = 14; x <= 16; ++x)
      zone[static_cast<std::size_t>(at(m, x, y))] = 1;
  const std::vector<char> grown = grow_zone(m, zone, 200);
  for (std::size_t b = 0; b < zone.size(); ++b) {
    if (zone[b]) {
      EXPECT_TRUE(grown[b]) << "a flagged block left out: " << b;
    }
  }
  EXPECT_EQ(near(m, grown, 3, 3, 6), 25);
  EXPECT_EQ(near(m, grown, 15, 15, 10), 217);
  int total = 0;
  for (char g : grown)
    total += g;
  EXPECT_EQ(total, 25 + 217);
}

// Blocks one apart are one island: a 1-block gap does not split what will merge in one ring.
TEST(GrowZone, BlocksOneApartAreOneIsland) {
  const Model m = grid();
  std::vector<char> zone(static_cast<std::size_t>(m.n_blocks()), 0);
  zone[static_cast<std::size_t>(at(m, 14, 15))] = 1;
  zone[static_cast<std::size_t>(at(m, 16, 15))] = 1;
  // One island of 2 blocks grown to 10: the first ring adds the 7 blocks at grid distance 1
  // from either (the one between them once), 9 in all; the second the 12 at distance 2, 21 in
  // all. As two islands with shares of 5, the first would stop at 5 and the second take one
  // more ring of 7: 16.
  const std::vector<char> grown = grow_zone(m, zone, 10);
  int total = 0;
  for (char g : grown)
    total += g;
  EXPECT_EQ(total, 21);
}

// An island that cannot take its share (hemmed in by `within`) leaves it to the others: the
// zone still reaches the target.
TEST(GrowZone, AnIslandHemmedInLeavesItsShareToTheRest) {
  const Model m = grid();
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
  EXPECT_GE(total, 100);
  EXPECT_EQ(near(m, grown, 3, 3, 6), 1);
}

}  // namespace
}  // namespace bimrock
