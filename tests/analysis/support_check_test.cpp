// Unsupported structures are reported by naming the blocks that can move, never solved.
#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/support_check.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

CaseSpec two_columns() {
  // Two separate columns of two blocks each (not touching): [0,1]x[0,2] and [2,3]x[0,2].
  CaseSpec c;
  c.file = "case.yaml";
  c.block_materials = {testing::rock(10e9, 0.2)};
  c.joint_materials = {testing::springs("joint", 1e10, 1e10)};
  std::vector<Polygon> p = brick_pattern(1, 2, 1.0, 1.0, Stagger::none);
  for (const Polygon& q : brick_pattern(1, 2, 1.0, 1.0, Stagger::none, Vec2(2.0, 0.0)))
    p.push_back(q);
  c.blocks = testing::blocks_of(p);
  c.default_joint = "joint";
  return c;
}

std::vector<int> free_blocks(const CaseSpec& c) {
  try {
    check_supports(build_model(c));
  } catch (const ModelError& e) {
    return e.blocks();
  }
  return {};
}

TEST(SupportCheck, FullySupportedStructurePasses) {
  CaseSpec c = two_columns();
  c.supports.push_back(testing::fixed({0, 0}, {3, 0}));
  EXPECT_TRUE(free_blocks(c).empty());
}

TEST(SupportCheck, NamesTheGroupWithoutSupport) {
  CaseSpec c = two_columns();
  c.supports.push_back(testing::fixed({0, 0}, {1, 0}));
  EXPECT_EQ(free_blocks(c), (std::vector<int>{2, 3}));
}

TEST(SupportCheck, RollersAlongOneLineLeaveASlidingMotionFree) {
  CaseSpec c = two_columns();
  c.supports.push_back(testing::roller({0, 0}, {3, 0}));
  EXPECT_EQ(free_blocks(c), (std::vector<int>{0, 1}));
}

TEST(SupportCheck, MessageNamesBlocksWithTheirLines) {
  CaseSpec c = two_columns();
  c.supports.push_back(testing::fixed({0, 0}, {1, 0}));
  try {
    solve_elastic(build_model(c));
    FAIL() << "an unsupported structure was solved";
  } catch (const ModelError& e) {
    EXPECT_NE(std::string(e.what()).find("blocks[2] (line 3)"), std::string::npos) << e.what();
  }
}

TEST(SupportCheck, JointsWithoutShearStiffnessAreCaughtByTheFactorization) {
  // Two stacked blocks, the lower one fixed, joined by a joint with k_s = 0: the upper block
  // slides freely. The rigid-group check passes (the joint holds in normal direction), the
  // Cholesky factorization breaks down and names the upper block.
  CaseSpec c;
  c.file = "case.yaml";
  c.block_materials = {testing::rock(10e9, 0.2)};
  c.joint_materials = {testing::springs("slippery", 1e10, 0.0)};
  c.blocks = testing::blocks_of(brick_pattern(1, 2, 1.0, 1.0, Stagger::none));
  c.default_joint = "slippery";
  c.supports.push_back(testing::fixed({0, 0}, {1, 0}));
  try {
    solve_elastic(build_model(c));
    FAIL() << "a mechanism was solved";
  } catch (const ModelError& e) {
    EXPECT_EQ(e.blocks(), std::vector<int>{1}) << e.what();
  }
}

}  // namespace
}  // namespace bimrock
