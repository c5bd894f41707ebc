// select_blocks on six unit squares in two rows of three, numbered row by row from the bottom
// left, so block k has its centroid at (k % 3 + 0.5, k / 3 + 0.5); blocks 4 and 5 are of
// material "lining". Every expected list is read off that layout.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/model/block_selector.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

Model grid_model() {
  CaseSpec c;
  c.file = "case.yaml";
  BlockMaterial lining = testing::rock(30e9, 0.2);
  lining.name = "lining";
  c.block_materials = {testing::rock(10e9, 0.2), lining};
  c.joint_materials = {testing::springs("joint", 1e10, 5e9)};
  for (int k = 0; k < 6; ++k) {
    const double x = k % 3;
    const double y = k / 3;
    c.blocks.push_back({Polygon{{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}},
                        k >= 4 ? "lining" : "rock",
                        {k + 1, "blocks[" + std::to_string(k) + "]"}});
  }
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({0, 0}, {3, 0}));
  return build_model(c);
}

BlockSelector region(std::vector<Vec2> vertices) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::region;
  s.region.vertices = std::move(vertices);
  s.source = {7, "stages[1].excavate.region"};
  return s;
}

BlockSelector box(Vec2 lo, Vec2 hi) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::box;
  s.box = BBox{lo, hi};
  s.source = {7, "stages[1].excavate.box"};
  return s;
}

BlockSelector material(const std::string& name) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::material;
  s.material = name;
  s.source = {7, "stages[1].install.material"};
  return s;
}

BlockSelector list(std::vector<int> blocks) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::list;
  s.blocks = std::move(blocks);
  s.source = {7, "stages[1].install.blocks"};
  return s;
}

std::string selection_error_of(const Model& m, const BlockSelector& s) {
  try {
    select_blocks(m, s);
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.item() + ": " + e.message();
  }
  return "";
}

using Blocks = std::vector<int>;

TEST(BlockSelector, ARegionPicksTheCentroidsInsideEvenWhereItIsNotConvex) {
  const Model m = grid_model();
  // An L: the bottom row and the left half of the top row. Its bounding box holds every
  // centroid, so the polygon itself decides.
  EXPECT_EQ(select_blocks(m, region({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}})),
            (Blocks{0, 1, 2, 3}));
  // A triangle under the line x + y = 3: centroids with x + y < 3 and those on it (blocks 2, 4).
  EXPECT_EQ(select_blocks(m, region({{0, 0}, {3, 0}, {0, 3}})), (Blocks{0, 1, 2, 3, 4}));
}

TEST(BlockSelector, ACentroidOnTheBoundaryCountsWithinTheTolerance) {
  const Model m = grid_model();  // tolerance 1e-9 times the diagonal sqrt(13): 3.6e-9 m
  EXPECT_EQ(select_blocks(m, region({{1.5, 0}, {3, 0}, {3, 1}, {1.5, 1}})), (Blocks{1, 2}));
  EXPECT_EQ(select_blocks(m, region({{1.5 + 1e-9, 0}, {3, 0}, {3, 1}, {1.5 + 1e-9, 1}})),
            (Blocks{1, 2}));
  EXPECT_EQ(select_blocks(m, region({{1.5 + 1e-6, 0}, {3, 0}, {3, 1}, {1.5 + 1e-6, 1}})),
            (Blocks{2}));
  EXPECT_EQ(select_blocks(m, box({0, 0}, {1.5, 0.5})), (Blocks{0, 1}));
  EXPECT_EQ(select_blocks(m, box({0, 0}, {1.5 - 1e-9, 0.5})), (Blocks{0, 1}));
  EXPECT_EQ(select_blocks(m, box({0, 0}, {1.5 - 1e-6, 0.5})), (Blocks{0}));
}

TEST(BlockSelector, ABoxPicksTheCentroidsInside) {
  const Model m = grid_model();
  EXPECT_EQ(select_blocks(m, box({1, 0}, {3, 2})), (Blocks{1, 2, 4, 5}));
  EXPECT_EQ(select_blocks(m, box({0.6, 0.6}, {1.4, 1.4})), Blocks{});  // between centroids
}

TEST(BlockSelector, AMaterialPicksItsBlocks) {
  const Model m = grid_model();
  EXPECT_EQ(select_blocks(m, material("lining")), (Blocks{4, 5}));
  EXPECT_EQ(select_blocks(m, material("rock")), (Blocks{0, 1, 2, 3}));
}

TEST(BlockSelector, AListIsSortedOnce) {
  EXPECT_EQ(select_blocks(grid_model(), list({5, 0, 3, 0})), (Blocks{0, 3, 5}));
}

TEST(BlockSelector, RejectsWhatSelectsNothingKnownNamingTheItem) {
  const Model m = grid_model();
  EXPECT_EQ(selection_error_of(m, list({2, 6})),
            "7: stages[1].install.blocks: there is no block 6: the model's 6 blocks are "
            "numbered from 0 to 5");
  EXPECT_EQ(selection_error_of(m, list({-1})),
            "7: stages[1].install.blocks: there is no block -1: the model's 6 blocks are "
            "numbered from 0 to 5");
  EXPECT_EQ(selection_error_of(m, material("granite")),
            "7: stages[1].install.material: unknown material 'granite'");
  EXPECT_EQ(selection_error_of(m, box({2, 2}, {1, 1})),
            "7: stages[1].excavate.box: the first corner must be the lower-left one: [[xmin, "
            "ymin], [xmax, ymax]]");
  EXPECT_EQ(selection_error_of(m, box({0, 0}, {std::nan(""), 1})),
            "7: stages[1].excavate.box: the box's corners must be finite points");
}

TEST(BlockSelector, RejectsARegionThatIsNotAnOutline) {
  const Model m = grid_model();
  EXPECT_EQ(selection_error_of(m, region({{0, 0}, {2, 2}, {2, 0}, {0, 2}})),
            "7: stages[1].excavate.region: the outline intersects itself: edges 1 and 3 cross "
            "or touch");
  EXPECT_EQ(selection_error_of(m, region({{0, 0}, {0, 2}, {2, 2}, {2, 0}})),
            "7: stages[1].excavate.region: the vertices are clockwise; list them "
            "counter-clockwise");
  EXPECT_EQ(selection_error_of(m, region({{0, 0}, {1, 1}})),
            "7: stages[1].excavate.region: a polygon needs at least 3 vertices");
}

}  // namespace
}  // namespace bimrock
