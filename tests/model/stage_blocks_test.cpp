// Which blocks each stage excavates and installs, and which are present during each stage, on
// six unit squares in two rows of three, numbered row by row from the bottom left (block k has
// its centroid at (k % 3 + 0.5, k / 3 + 0.5)). Every expectation is read off that layout and the
// stages written here; every error names the stage's item.
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include <bimrock/model/stage_blocks.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

CaseSpec grid_case() {
  CaseSpec c;
  c.file = "case.yaml";
  BlockMaterial lining = testing::rock(30e9, 0.2, 24e3);
  lining.name = "lining";
  c.block_materials = {testing::rock(10e9, 0.2, 26e3), lining};
  c.joint_materials = {testing::springs("joint", 1e10, 5e9)};
  for (int k = 0; k < 6; ++k) {
    const double x = k % 3;
    const double y = k / 3;
    c.blocks.push_back({Polygon{{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}},
                        k == 5 ? "lining" : "rock",
                        {k + 1, "blocks[" + std::to_string(k) + "]"}});
  }
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({0, 0}, {3, 0}));
  c.monitors.push_back({"crown", {1.5, 1.9}, {0, "monitors[0]"}});  // in block 4
  return c;
}

// Stage k of the case, named "s<k>" with item "stages[<k>]" on line 10 k.
StageSpec& stage(CaseSpec& c, int k) {
  while (static_cast<int>(c.stages.size()) <= k) {
    const int n = static_cast<int>(c.stages.size());
    StageSpec st;
    st.name = "s" + std::to_string(n);
    st.source = {10 * n, "stages[" + std::to_string(n) + "]"};
    c.stages.push_back(st);
  }
  return c.stages[static_cast<std::size_t>(k)];
}

BlockSelector blocks(std::vector<int> indices, const std::string& item) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::list;
  s.blocks = std::move(indices);
  s.source = {1, item};
  return s;
}

BlockSelector box_selector(Vec2 lo, Vec2 hi, const std::string& item) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::box;
  s.box = BBox{lo, hi};
  s.source = {1, item};
  return s;
}

std::string item_error_of(const CaseSpec& c) {
  try {
    build_model(c);
  } catch (const InputError& e) {
    return e.item() + ": " + e.message();
  }
  return "";
}

using Present = std::vector<char>;

// s0 in situ; s1 excavates block 4 (a box), 40% released; s2 installs block 5 (its material);
// s3 excavates block 3; s4 excavates block 5 again.
CaseSpec sequence() {
  CaseSpec c = grid_case();
  stage(c, 0).loads.gravity = {0, -1};
  stage(c, 1).excavate = box_selector({1, 1}, {2, 2}, "stages[1].excavate.box");
  stage(c, 1).release = 0.4;
  BlockSelector lining;
  lining.kind = BlockSelector::Kind::material;
  lining.material = "lining";
  lining.source = {21, "stages[2].install.material"};
  stage(c, 2).install = lining;
  stage(c, 3).excavate = blocks({3}, "stages[3].excavate.blocks");
  stage(c, 4).excavate = blocks({5}, "stages[4].excavate.blocks");
  return c;
}

TEST(StageBlocks, ResolvesEachStagesBlocksAndRelease) {
  const Model m = build_model(sequence());
  ASSERT_EQ(m.stages.size(), 5u);
  EXPECT_EQ(m.stages[0].excavated, std::vector<int>{});
  EXPECT_EQ(m.stages[1].excavated, std::vector<int>{4});
  EXPECT_EQ(m.stages[1].release, 0.4);
  EXPECT_EQ(m.stages[2].installed, std::vector<int>{5});
  EXPECT_EQ(m.stages[2].release, 1.0);
  EXPECT_EQ(m.stages[3].excavated, std::vector<int>{3});
  EXPECT_EQ(m.stages[4].excavated, std::vector<int>{5});
}

TEST(StageBlocks, BlocksPresentFollowTheStages) {
  const Model m = build_model(sequence());
  EXPECT_EQ(blocks_present(m, -1), (Present{1, 1, 1, 1, 1, 0}));  // 5 waits for s2
  EXPECT_EQ(blocks_present(m, 0), (Present{1, 1, 1, 1, 1, 0}));
  EXPECT_EQ(blocks_present(m, 1), (Present{1, 1, 1, 1, 0, 0}));
  EXPECT_EQ(blocks_present(m, 2), (Present{1, 1, 1, 1, 0, 1}));
  EXPECT_EQ(blocks_present(m, 3), (Present{1, 1, 1, 0, 0, 1}));
  EXPECT_EQ(blocks_present(m, 4), (Present{1, 1, 1, 0, 0, 0}));
  EXPECT_THROW(blocks_present(m, 5), std::out_of_range);
  EXPECT_THROW(blocks_present(m, -2), std::out_of_range);
}

TEST(StageBlocks, EveryBlockIsPresentWithoutExcavationOrInstallation) {
  CaseSpec c = grid_case();
  stage(c, 0).loads.gravity = {0, -1};
  const Model m = build_model(c);
  EXPECT_EQ(blocks_present(m, -1), Present(6, 1));
  EXPECT_EQ(blocks_present(m, 0), Present(6, 1));
}

TEST(StageBlocks, RebuildResolvesTheStagesAgain) {
  const Model built = build_model(grid_case());
  const Model m = rebuild_model(built, sequence());
  EXPECT_EQ(m.stages[1].excavated, std::vector<int>{4});
  EXPECT_EQ(blocks_present(m, 2), (Present{1, 1, 1, 1, 0, 1}));
}

TEST(StageBlocks, RejectsASelectorThatPicksNoBlock) {
  CaseSpec c = grid_case();
  stage(c, 1).excavate = box_selector({5, 5}, {6, 6}, "stages[1].excavate.box");
  EXPECT_EQ(item_error_of(c),
            "stages[1].excavate.box: selects no block: no block's centroid lies in the box");
}

TEST(StageBlocks, RejectsExcavatingABlockAlreadyExcavated) {
  CaseSpec c = grid_case();
  stage(c, 0).excavate = blocks({4}, "stages[0].excavate.blocks");
  stage(c, 2).excavate = box_selector({1, 1}, {3, 2}, "stages[2].excavate.box");  // blocks 4 and 5
  EXPECT_EQ(item_error_of(c),
            "stages[2].excavate.box: block 4 (centroid (1.5, 1.5)) is absent at this stage: "
            "excavated by stages[0] ('s0')");
}

TEST(StageBlocks, RejectsExcavatingABlockInstalledOnlyLater) {
  CaseSpec c = grid_case();
  stage(c, 1).excavate = blocks({2, 5}, "stages[1].excavate.blocks");
  stage(c, 3).install = blocks({5}, "stages[3].install.blocks");
  EXPECT_EQ(item_error_of(c),
            "stages[1].excavate.blocks: block 5 (centroid (2.5, 1.5)) is absent at this stage: "
            "not installed until stages[3] ('s3'), as a block some stage installs is absent "
            "until then");
}

TEST(StageBlocks, RejectsInstallingABlockTwice) {
  CaseSpec c = grid_case();
  stage(c, 1).install = blocks({5}, "stages[1].install.blocks");
  stage(c, 2).excavate = blocks({5}, "stages[2].excavate.blocks");
  stage(c, 3).install = blocks({4, 5}, "stages[3].install.blocks");
  EXPECT_EQ(item_error_of(c),
            "stages[3].install.blocks: block 5 (centroid (2.5, 1.5)) is already installed by "
            "stages[1] ('s1'): a block is installed once");
}

TEST(StageBlocks, RejectsExcavatingAndInstallingTheSameBlockInOneStage) {
  CaseSpec c = grid_case();
  stage(c, 1).excavate = blocks({3, 4}, "stages[1].excavate.blocks");
  stage(c, 1).install = blocks({4}, "stages[1].install.blocks");
  EXPECT_EQ(item_error_of(c),
            "stages[1].install.blocks: block 4 (centroid (1.5, 1.5)) is also excavated by this "
            "stage");
}

TEST(StageBlocks, RejectsExcavatingEveryBlockPresent) {
  CaseSpec c = grid_case();
  stage(c, 0).install = blocks({5}, "stages[0].install.blocks");
  stage(c, 1).excavate = blocks({0, 1, 2, 3, 4, 5}, "stages[1].excavate.blocks");
  EXPECT_EQ(item_error_of(c),
            "stages[1].excavate.blocks: excavates every block present at this stage: at least "
            "one must remain");
  stage(c, 1).excavate = blocks({0, 1, 2, 3, 4}, "stages[1].excavate.blocks");  // 5 remains
  EXPECT_EQ(item_error_of(c), "");
}

TEST(StageBlocks, RejectsAReleaseBeforeAnyExcavationOrOutOfRange) {
  CaseSpec c = grid_case();
  stage(c, 0).release = 0.5;
  stage(c, 1).excavate = blocks({4}, "stages[1].excavate.blocks");
  EXPECT_EQ(item_error_of(c),
            "stages[0].release: no stage up to this one excavates a block: release applies to "
            "the forces of excavated blocks not yet released");
  stage(c, 0).release = 1.0;
  stage(c, 2).release = 0.5;  // after the excavation: the forces not yet released
  EXPECT_EQ(item_error_of(c), "");
  stage(c, 1).release = 0.0;
  EXPECT_EQ(item_error_of(c),
            "stages[1].release: must lie in (0, 1]: the fraction of the unreleased excavation "
            "forces released");
  stage(c, 1).release = std::nan("");
  EXPECT_NE(item_error_of(c).find("stages[1].release: must lie in (0, 1]"), std::string::npos);
}

TEST(StageBlocks, RejectsAPointLoadOnAnAbsentBlock) {
  CaseSpec c = grid_case();
  stage(c, 1).excavate = blocks({4}, "stages[1].excavate.blocks");
  stage(c, 2).loads.points.push_back({{1.5, 1.5}, {1e3, 0}, {25, "stages[2].loads.points[0]"}});
  EXPECT_EQ(item_error_of(c),
            "stages[2].loads.points[0]: acts on block 4 (centroid (1.5, 1.5)), which is absent "
            "during this stage: excavated by stages[1] ('s1')");
  // Before block 5 is installed, its point loads have nothing to act on.
  CaseSpec d = grid_case();
  stage(d, 0).loads.points.push_back({{2.5, 1.5}, {1e3, 0}, {5, "stages[0].loads.points[0]"}});
  stage(d, 1).install = blocks({5}, "stages[1].install.blocks");
  EXPECT_NE(
      item_error_of(d).find("stages[0].loads.points[0]: acts on block 5 (centroid (2.5, 1.5)), "
                            "which is absent during this stage: not installed until stages[1]"),
      std::string::npos)
      << item_error_of(d);
  // In the stage that installs it, it is there.
  d.stages[0].loads.points.clear();
  stage(d, 1).loads.points.push_back({{2.5, 1.5}, {1e3, 0}, {15, "stages[1].loads.points[0]"}});
  EXPECT_EQ(item_error_of(d), "");
}

TEST(StageBlocks, RejectsATractionOnAnAbsentBlock) {
  CaseSpec c = grid_case();
  stage(c, 1).excavate = blocks({4}, "stages[1].excavate.blocks");
  stage(c, 1).loads.tractions.push_back(
      {testing::on_line({0, 2}, {3, 2}), -1e5, 0.0, {15, "stages[1].loads.tractions[0]"}});
  EXPECT_EQ(item_error_of(c),
            "stages[1].loads.tractions[0]: acts on an edge of block 4 (centroid (1.5, 1.5)), "
            "which is absent during this stage: excavated by stages[1] ('s1')");
}

TEST(StageBlocks, MonitorsMayFollowAnAbsentBlockButNotControlIt) {
  CaseSpec c = grid_case();  // the monitor "crown" is in block 4
  stage(c, 1).excavate = blocks({4}, "stages[1].excavate.blocks");
  stage(c, 2).loads.gravity = {0, -1};
  EXPECT_EQ(item_error_of(c), "");
  stage(c, 2).control = DisplacementControlSpec{"crown", {0, 1}, 0.01, {22, "stages[2].control"}};
  EXPECT_EQ(item_error_of(c),
            "stages[2].control: monitor 'crown' follows block 4 (centroid (1.5, 1.5)), which is "
            "absent during this stage: excavated by stages[1] ('s1')");
}

TEST(StageBlocks, CopiesTheInitialStressOfAStagedCaseOnly) {
  CaseSpec c = grid_case();
  InitialStressSpec s;
  s.uniform = {-1e6, -2e6, 0.0};
  s.gravity = InitialStressSpec::Gravity{120.0, 26e3, 0.5};
  s.allow_yield = true;
  s.source = {30, "initial_stress"};
  c.initial_stress = s;
  EXPECT_EQ(item_error_of(c),
            "initial_stress: is the stress before the first stage: give stages (an elastic "
            "analysis starts unstressed)");
  stage(c, 0).loads.gravity = {0, -1};
  const Model m = build_model(c);
  ASSERT_TRUE(m.initial_stress.has_value());
  EXPECT_EQ(m.initial_stress->uniform, Eigen::Vector3d(-1e6, -2e6, 0.0));
  EXPECT_EQ(m.initial_stress->gravity->ground_level, 120.0);
  EXPECT_EQ(m.initial_stress->gravity->unit_weight, 26e3);
  EXPECT_EQ(m.initial_stress->gravity->k0, 0.5);
  EXPECT_TRUE(m.initial_stress->allow_yield);
  c.initial_stress->gravity->unit_weight = 0.0;
  EXPECT_EQ(item_error_of(c), "initial_stress.gravity: unit_weight must be positive");
  c.initial_stress->gravity->unit_weight = 26e3;
  c.initial_stress->uniform.x() = std::numeric_limits<double>::infinity();
  EXPECT_EQ(item_error_of(c), "initial_stress.stress: must be finite");
}

}  // namespace
}  // namespace bimrock
