// Verification: yield of the blocks (Mohr-Coulomb and Tresca in plane strain on the block's mean
// stress, linearized by the polygon of p planes inscribed in the circle; docs/case-file.md).
//
// A w x h rectangle (one block, or irregular blocks joined by continuum interfaces: a block that
// yields alone then carries a mechanism only together with the rest) on rollers along x = 0 and y =
// 0 is compressed by a uniform pressure p on its top: the uniform stress sigma_y = -p, sigma_x =
// tau_xy = 0 is exact for the block model (one block, or several joined by continuum interfaces),
// so collapse comes when that stress reaches the linearized criterion. With the planes of
// docs/case-file.md (plane 0 normal to the (sigma_x - sigma_y)/2 axis) the path meets plane 0 at
// distance c cos(pi/p) from the axis:
//   Tresca:        p_u = 2 c cos(pi/p)
//   Mohr-Coulomb:  p/2 - (p/2) sin(phi) cos(pi/p) = c cos(phi) cos(pi/p), so
//                  p_u = 2 c cos(phi) cos(pi/p) / (1 - sin(phi) cos(pi/p)),
// which tends to the unconfined compressive strength 2 c cos(phi) / (1 - sin(phi)) as p grows.
// The collapse must be bracketed to 1e-4 of p_u, whatever the number of blocks.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"

namespace bimrock {
namespace {

constexpr double kSpecimenCohesion = 1e6;
constexpr double kSpecimenWidth = 2.0;
constexpr double kSpecimenHeight = 1.0;

// cuts = 0: one block; otherwise irregular blocks from that many random cuts, joined by
// continuum (penalty) interfaces.
CaseSpec compressed(const BlockStrength& strength, int cuts, double p_max) {
  CaseSpec c;
  c.file = "block_strength";
  c.block_materials = {testing::rock(10e9, 0.25)};
  c.block_materials[0].strength = strength;
  c.joint_materials = {testing::continuum(kDefaultPenaltyFactor)};
  c.blocks =
      cuts == 0
          ? testing::blocks_of({Polygon{{{0, 0},
                                         {kSpecimenWidth, 0},
                                         {kSpecimenWidth, kSpecimenHeight},
                                         {0, kSpecimenHeight}}}})
          : testing::blocks_of(testing::irregular_blocks(kSpecimenWidth, kSpecimenHeight, cuts, 7));
  c.default_joint = "continuum";
  c.supports.push_back(testing::roller({0, 0}, {kSpecimenWidth, 0}));
  c.supports.push_back(testing::roller({0, 0}, {0, kSpecimenHeight}));
  StageSpec load{"load", {}, 20, std::nullopt, {0, "load"}};
  load.loads.tractions.push_back(
      testing::pressure_on({0, kSpecimenHeight}, {kSpecimenWidth, kSpecimenHeight}, -p_max));
  c.stages = {load};
  return c;
}

void expect_collapse_at(const CaseSpec& c, double p_max, double expected) {
  PlasticOptions o;
  o.bracket_tolerance = 1e-6;
  const PlasticResult r = run_plastic_analysis(build_model(c), o);
  ASSERT_TRUE(r.collapse.has_value());
  const double carried = r.collapse->carried * p_max;
  const double failed = r.collapse->failed * p_max;
  std::printf("%zu blocks: collapse bracket [%.6f, %.6f] MPa, expected %.6f MPa\n", c.blocks.size(),
              carried / 1e6, failed / 1e6, expected / 1e6);
  EXPECT_LE(carried, expected * (1 + 1e-9));
  EXPECT_GE(failed, expected * (1 - 1e-9));
  EXPECT_NEAR(carried, expected, 1e-4 * expected);
  EXPECT_NEAR(failed, expected, 1e-4 * expected);
  // The mechanism is plastic flow of the blocks (no joint can yield here).
  ASSERT_FALSE(r.collapse->mechanism.empty());
  for (const MechanismEntry& e : r.collapse->mechanism)
    EXPECT_FALSE(r.points[e.point].is_interface());
}

struct Variant {
  int cuts, planes;
};

class BlockStrengthTest : public ::testing::TestWithParam<Variant> {};

TEST_P(BlockStrengthTest, TrescaCollapsesAtTwiceTheCohesionOfTheInscribedPolygon) {
  BlockStrength s;
  s.criterion = BlockStrength::Criterion::tresca;
  s.cohesion = kSpecimenCohesion;
  s.planes = GetParam().planes;
  const double expected = 2 * kSpecimenCohesion * std::cos(M_PI / s.planes);
  expect_collapse_at(compressed(s, GetParam().cuts, 3 * kSpecimenCohesion), 3 * kSpecimenCohesion,
                     expected);
}

TEST_P(BlockStrengthTest, MohrCoulombCollapsesAtItsUnconfinedStrength) {
  const double phi = 30.0 * M_PI / 180.0;
  BlockStrength s;
  s.criterion = BlockStrength::Criterion::mohr_coulomb;
  s.cohesion = kSpecimenCohesion;
  s.friction = std::sin(phi);
  s.dilation = std::sin(phi);
  s.planes = GetParam().planes;
  const double ci = std::cos(M_PI / s.planes);
  const double expected = 2 * kSpecimenCohesion * std::cos(phi) * ci / (1 - std::sin(phi) * ci);
  expect_collapse_at(compressed(s, GetParam().cuts, 5 * kSpecimenCohesion), 5 * kSpecimenCohesion,
                     expected);
}

INSTANTIATE_TEST_SUITE_P(Blocks, BlockStrengthTest,
                         ::testing::Values(Variant{0, 24}, Variant{0, 8}, Variant{6, 24}),
                         [](const auto& p) {
                           return std::to_string(p.param.cuts) + "cuts_" +
                                  std::to_string(p.param.planes) + "planes";
                         });

}  // namespace
}  // namespace bimrock
