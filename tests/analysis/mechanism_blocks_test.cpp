// How blocks take part in a collapse mechanism, against hand-worked velocities (eq. 1:
// u = u0 - theta (y - y0), v = v0 + theta (x - x0), strains zero here).
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/mechanism_blocks.hpp>

namespace bimrock {
namespace {

Block block_of(std::vector<Vec2> corners, Vec2 centroid) {
  Block b;
  b.polygon = Polygon{std::move(corners)};
  b.centroid = centroid;
  return b;
}

// A 1 m x 2.5 m block [0, 1] x [0, 2.5] toppling clockwise (theta = -1) about its toe (1, 0):
// at p the velocity is theta x (p - toe) = (-theta y, theta (x - 1)), so at the centroid
// (0.5, 1.25): u0 = 1.25, v0 = 0.5. Its fastest corner is the far top corner (0, 2.5), at
// |theta| sqrt(1 + 2.5^2) = 2.6926 from the toe.
const std::vector<Vec2> kTall{{0, 0}, {1, 0}, {1, 2.5}, {0, 2.5}};
const Vec2 kTallCentroid(0.5, 1.25);
const Vec6 kToppling = (Vec6() << 1.25, 0.5, -1.0, 0, 0, 0).finished();

const std::vector<Vec2> kSquare{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const Vec2 kSquareCentroid(0.5, 0.5);

TEST(MechanismBlocks, ToppleAboutTheToeLeavesTheToeStillAndMovesTheFarCornerFastest) {
  EXPECT_NEAR((block_Q(kTallCentroid, Vec2(1, 0)) * kToppling).norm(), 0.0, 1e-15);
  EXPECT_NEAR(fastest_corner_speed(kToppling, kTallCentroid, kTall), std::sqrt(7.25), 1e-14);
}

TEST(MechanismBlocks, ATranslatingBlockMoves) {
  const Vec6 d = (Vec6() << 0.6, -0.8, 0, 0, 0, 0).finished();
  const double speed = fastest_corner_speed(d, kSquareCentroid, kSquare);
  EXPECT_NEAR(speed, 1.0, 1e-15);
  EXPECT_EQ(classify_block_motion(d, kSquareCentroid, kSquare, speed, 1.0), BlockMotion::moves);
}

TEST(MechanismBlocks, ABlockTopplingAboutItsCornerRotates) {
  // Centre of rotation at the toe: |(u0, v0)| = 1.346 = |theta| R with R = 1.346 (centroid to
  // a corner), within kRotationReach R.
  const double speed = fastest_corner_speed(kToppling, kTallCentroid, kTall);
  EXPECT_EQ(classify_block_motion(kToppling, kTallCentroid, kTall, speed, speed),
            BlockMotion::rotates);
}

TEST(MechanismBlocks, ASlideWithALittleRotationMoves) {
  // theta = 0.1 on the unit square (R = 0.707): the centre of rotation lies 10 m away, beyond
  // 2 R = 1.41 m; with theta = 1 it lies 1 m away, within.
  const Vec6 slide = (Vec6() << 1, 0, 0.1, 0, 0, 0).finished();
  const double slow = fastest_corner_speed(slide, kSquareCentroid, kSquare);
  EXPECT_EQ(classify_block_motion(slide, kSquareCentroid, kSquare, slow, slow), BlockMotion::moves);
  const Vec6 spin = (Vec6() << 1, 0, 1, 0, 0, 0).finished();
  const double fast = fastest_corner_speed(spin, kSquareCentroid, kSquare);
  EXPECT_EQ(classify_block_motion(spin, kSquareCentroid, kSquare, fast, fast),
            BlockMotion::rotates);
}

TEST(MechanismBlocks, ABlockFarSlowerThanTheFastestStands) {
  const Vec6 d = (Vec6() << 1e-4, 0, 0, 0, 0, 0).finished();
  EXPECT_EQ(classify_block_motion(d, kSquareCentroid, kSquare, 1e-4, 1.0), BlockMotion::stands);
  // Just above the standing fraction it moves.
  EXPECT_EQ(classify_block_motion(d, kSquareCentroid, kSquare, 1e-4, 0.05), BlockMotion::moves);
}

TEST(MechanismBlocks, NormalizedSoThatTheFastestCornerMovesAtOne) {
  // Block 0 translates at 2 m per unit, block 1 topples (fastest corner 2.6926), block 2 creeps
  // elastically at 1e-6.
  Model model;
  model.blocks = {block_of(kSquare, kSquareCentroid), block_of(kTall, kTallCentroid),
                  block_of({{3, 0}, {4, 0}, {4, 1}, {3, 1}}, Vec2(3.5, 0.5))};
  Eigen::VectorXd direction = Eigen::VectorXd::Zero(18);
  direction(0) = 2.0;
  direction.segment<6>(6) = kToppling;
  direction(12) = 1e-6;
  const MechanismBlocks m = mechanism_blocks(model, direction);
  const double fastest = std::sqrt(7.25);
  EXPECT_NEAR(m.scale, fastest, 1e-14);
  ASSERT_EQ(m.blocks.size(), 3u);
  EXPECT_NEAR(m.blocks[0].velocity(0), 2.0 / fastest, 1e-14);
  EXPECT_NEAR(m.blocks[0].speed, 2.0 / fastest, 1e-14);
  EXPECT_NEAR(m.blocks[1].speed, 1.0, 1e-14);
  EXPECT_NEAR(m.blocks[1].velocity(2), -1.0 / fastest, 1e-14);
  EXPECT_EQ(m.blocks[0].motion, BlockMotion::moves);
  EXPECT_EQ(m.blocks[1].motion, BlockMotion::rotates);
  EXPECT_EQ(m.blocks[2].motion, BlockMotion::stands);
  const Eigen::VectorXd stacked = stacked_velocities(m);
  EXPECT_NEAR((stacked - direction / fastest).norm(), 0.0, 1e-14);
}

TEST(MechanismBlocks, NoDirectionLeavesEveryBlockStanding) {
  Model model;
  model.blocks = {block_of(kSquare, kSquareCentroid)};
  const MechanismBlocks m = mechanism_blocks(model, Eigen::VectorXd());
  EXPECT_EQ(m.scale, 0.0);
  EXPECT_EQ(m.blocks[0].motion, BlockMotion::stands);
  EXPECT_STREQ(block_motion_name(m.blocks[0].motion), "stands");
}

}  // namespace
}  // namespace bimrock
