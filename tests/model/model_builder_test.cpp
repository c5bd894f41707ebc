// build_model turns a case into a model or names the offending item with its line.
#include <gtest/gtest.h>

#include <bimrock/model/model.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

CaseSpec square_pair() {
  CaseSpec c;
  c.file = "case.yaml";
  c.block_materials = {testing::rock(10e9, 0.2, 2.5e4)};
  c.joint_materials = {testing::springs("joint", 1e10, 5e9)};
  c.blocks = testing::blocks_of(brick_pattern(2, 1, 1.0, 1.0, Stagger::none));
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({0, 0}, {2, 0}));
  return c;
}

// Builds the case and returns the error's "line: item: message" or "" when it builds.
std::string error_of(const CaseSpec& c) {
  try {
    build_model(c);
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.item() + ": " + e.message();
  }
  return "";
}

TEST(ModelBuilder, ResolvesInterfacesSupportsAndStiffness) {
  const Model m = build_model(square_pair());
  ASSERT_EQ(m.n_blocks(), 2);
  ASSERT_EQ(m.n_interfaces(), 3);  // one joint + the two halves of the base
  EXPECT_FALSE(m.interfaces[0].is_support());
  EXPECT_DOUBLE_EQ(m.interfaces[0].normal_stiffness, 1e10);
  EXPECT_DOUBLE_EQ(m.interfaces[0].shear_stiffness, 5e9);
  EXPECT_TRUE(m.interfaces[1].is_support());
  // Rigid support: k = p E / sqrt(A) with p the default penalty factor.
  EXPECT_DOUBLE_EQ(m.interfaces[1].normal_stiffness, kDefaultPenaltyFactor * 10e9);
  EXPECT_TRUE(m.interfaces[1].normal.isApprox(Vec2(0, -1)));
}

TEST(ModelBuilder, SubdividedJointsSplitIntoEqualPieces) {
  CaseSpec c = square_pair();
  c.joint_materials[0].subdivisions = 4;
  const Model m = build_model(c);
  EXPECT_EQ(m.n_interfaces(), 4 + 2);
  EXPECT_NEAR(m.interfaces[1].segment.length(), 0.25, 1e-15);
}

TEST(ModelBuilder, RejectsAClockwiseBlockByItsLine) {
  CaseSpec c = square_pair();
  std::reverse(c.blocks[1].polygon.vertices.begin(), c.blocks[1].polygon.vertices.end());
  EXPECT_EQ(error_of(c), "2: blocks[1]: the vertices are clockwise; list them counter-clockwise");
}

TEST(ModelBuilder, RejectsANonConvexBlock) {
  CaseSpec c = square_pair();
  c.blocks[1].polygon.vertices = {{1, 0}, {2, 0}, {1.5, 0.5}, {2, 1}, {1, 1}};
  EXPECT_EQ(error_of(c), "2: blocks[1]: vertex 3 makes the polygon non-convex");
}

TEST(ModelBuilder, RejectsDuplicateVerticesAndZeroArea) {
  CaseSpec c = square_pair();
  c.blocks[0].polygon.vertices = {{0, 0}, {1, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(error_of(c), "1: blocks[0]: vertex 3 duplicates an earlier vertex");
  c.blocks[0].polygon.vertices = {{0, 0}, {0.5, 0}, {1, 0}};
  EXPECT_EQ(error_of(c), "1: blocks[0]: the polygon has zero area");
}

TEST(ModelBuilder, RejectsOverlappingBlocksNamingBoth) {
  CaseSpec c = square_pair();
  for (Vec2& v : c.blocks[1].polygon.vertices)
    v.x() -= 0.5;
  EXPECT_EQ(error_of(c),
            "2: blocks[1]: overlaps blocks[0] (line 1) (blocks may touch along edges "
            "but not overlap)");
}

TEST(ModelBuilder, RejectsAnUnknownMaterial) {
  CaseSpec c = square_pair();
  c.blocks[0].material = "granit";
  EXPECT_EQ(error_of(c), "1: blocks[0]: unknown material 'granit'");
}

TEST(ModelBuilder, RejectsNegativeOrNaNStiffness) {
  CaseSpec c = square_pair();
  c.joint_materials[0].normal_stiffness = -1.0;
  EXPECT_EQ(error_of(c), "0: joint: normal stiffness k_n must be positive");
  c.joint_materials[0].normal_stiffness = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of(c), "0: joint: normal stiffness k_n must be positive");
}

TEST(ModelBuilder, RejectsANaNVertex) {
  CaseSpec c = square_pair();
  c.blocks[1].polygon.vertices[2].y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(error_of(c), "2: blocks[1]: a vertex is not a finite number (NaN or infinity)");
}

TEST(ModelBuilder, RejectsASupportThatSelectsNothing) {
  CaseSpec c = square_pair();
  c.supports[0].where = testing::on_line({0, 5}, {2, 5});
  EXPECT_EQ(error_of(c), "0: supports: selects no boundary edge");
}

TEST(ModelBuilder, RejectsAPointLoadOutsideEveryBlock) {
  CaseSpec c = square_pair();
  c.loads.points.push_back({Vec2(3, 3), Vec2(1, 0), {7, "loads.points[0]"}});
  EXPECT_EQ(error_of(c), "7: loads.points[0]: the point (3.000000, 3.000000) lies in no block");
}

}  // namespace
}  // namespace bimrock
