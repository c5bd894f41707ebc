// What a picture of the blocks says about its own scale: the scale bar's length (1, 2 or 5
// times a power of ten, at most a fifth of the drawing) and the magnification of the
// displacements. Expected numbers worked by hand; the picture files themselves are drawn by
// cairo and checked to exist elsewhere (examples_test).
#include <gtest/gtest.h>

#include <bimrock/io/block_picture.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

TEST(BlockPicture, ScaleBarIsOneTwoOrFiveTimesAPowerOfTenWithinAFifth) {
  EXPECT_DOUBLE_EQ(scale_bar_length(100.0), 20.0);  // a fifth is 20
  EXPECT_DOUBLE_EQ(scale_bar_length(37.0), 5.0);    // 7.4: 5
  EXPECT_DOUBLE_EQ(scale_bar_length(9.0), 1.0);     // 1.8: 1
  EXPECT_DOUBLE_EQ(scale_bar_length(0.3), 0.05);    // 0.06: 0.05
  EXPECT_DOUBLE_EQ(scale_bar_length(12000.0), 2000.0);
}

TEST(BlockPicture, MagnificationShowsTheLargestCornerDisplacementAsAFractionOfTheSize) {
  CaseSpec c;
  c.file = "picture";
  c.block_materials = {testing::rock(1e9, 0.2)};
  c.joint_materials = {testing::springs("joint", 1e9, 1e9)};
  c.default_joint = "joint";
  c.blocks = testing::blocks_of({Polygon{{{0, 0}, {2, 0}, {2, 1}, {0, 1}}}});
  c.supports.push_back(testing::fixed({0, 0}, {2, 0}));
  const Model model = build_model(c);
  // A rotation theta = 1e-3 about the centroid (1, 0.5): the corners move by
  // theta * sqrt(1 + 0.25) = 1.118e-3 m; shown as 5% of a size of 10 m: x 447.2.
  Eigen::VectorXd u = Eigen::VectorXd::Zero(6);
  u(2) = 1e-3;
  EXPECT_NEAR(displacement_magnification(model, u, 0.05, 10.0), 0.5 / (1e-3 * std::sqrt(1.25)),
              1e-9);
  EXPECT_EQ(displacement_magnification(model, Eigen::VectorXd(), 0.05, 10.0), 0.0);
  EXPECT_EQ(displacement_magnification(model, Eigen::VectorXd::Zero(6), 0.05, 10.0), 0.0);
}

}  // namespace
}  // namespace bimrock
