// Strength reduction (analysis/strength_reduction.hpp) against its definition worked by hand:
// c / F, tan(phi) / F, sigma_t / F for joints (peak and residual), c / F and
// phi' = atan(tan(phi) / F) for blocks, the dilation capped at the reduced friction angle
// (associated flow kept associated, whichever way F goes), and only the selected materials
// changed.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/strength_reduction.hpp>

#include "support/incline_case.hpp"

namespace bimrock {
namespace {

using testing::kDeg;

Model two_materials() {
  testing::Incline in;
  in.friction_deg = 40.0;
  in.dilation_deg = 30.0;
  CaseSpec c = testing::incline_case(in);
  JointStrength& s = *c.joint_materials[0].strength;
  s.cohesion = {50e3, 10e3, 0.01};
  s.tensile = Softening::constant(20e3);
  BlockStrength rock;
  rock.cohesion = 1e6;
  rock.friction = std::sin(35.0 * kDeg);
  rock.dilation = std::sin(20.0 * kDeg);
  c.block_materials[0].strength = rock;
  return build_model(c);
}

TEST(StrengthReduction, DividesEveryStrengthOfTheSelectedMaterials) {
  const Model m = two_materials();
  const Model r = reduce_strength(m, all_strengths(m), 2.0);
  const JointStrength& j = *r.joint_materials[0].strength;
  EXPECT_DOUBLE_EQ(j.cohesion.peak, 25e3);
  EXPECT_DOUBLE_EQ(j.cohesion.residual, 5e3);
  EXPECT_DOUBLE_EQ(j.cohesion.distance, 0.01);  // softening distances are not strengths
  EXPECT_DOUBLE_EQ(j.friction.peak, std::tan(40.0 * kDeg) / 2.0);
  EXPECT_DOUBLE_EQ(j.tensile.peak, 10e3);
  // tan(30) = 0.577 is above the reduced tan(phi) = 0.420: capped there.
  EXPECT_DOUBLE_EQ(j.dilation, j.friction.peak);
  const BlockStrength& b = *r.block_materials[0].strength;
  EXPECT_DOUBLE_EQ(b.cohesion, 0.5e6);
  EXPECT_NEAR(b.friction, std::sin(std::atan(std::tan(35.0 * kDeg) / 2.0)), 1e-15);
  EXPECT_DOUBLE_EQ(b.dilation, b.friction);  // psi = 20 deg is above phi' = 19.30 deg: capped
}

TEST(StrengthReduction, KeepsAssociatedFlowAssociatedAndOtherDilationsBelowTheFriction) {
  const Model m = two_materials();
  const Model associated = with_associated_flow(m);
  for (const double factor : {0.5, 2.0}) {
    // F < 1 raises the friction: associated flow follows it, a smaller dilation is kept.
    const Model a = reduce_strength(associated, all_strengths(associated), factor);
    EXPECT_DOUBLE_EQ(a.joint_materials[0].strength->dilation, std::tan(40.0 * kDeg) / factor);
    EXPECT_NEAR(a.block_materials[0].strength->dilation,
                std::sin(std::atan(std::tan(35.0 * kDeg) / factor)), 1e-15);
  }
  const Model raised = reduce_strength(m, all_strengths(m), 0.5);
  EXPECT_DOUBLE_EQ(raised.joint_materials[0].strength->dilation, std::tan(30.0 * kDeg));
  EXPECT_DOUBLE_EQ(raised.block_materials[0].strength->dilation, std::sin(20.0 * kDeg));
}

TEST(StrengthReduction, LeavesTheOthersAndTheStiffnessAlone) {
  const Model m = two_materials();
  StrengthSelection joints_only = all_strengths(m);
  joints_only.block_materials.assign(m.block_materials.size(), 0);
  const Model r = reduce_strength(m, joints_only, 1.5);
  EXPECT_DOUBLE_EQ(r.block_materials[0].strength->cohesion, 1e6);
  EXPECT_DOUBLE_EQ(r.joint_materials[0].strength->cohesion.peak, 50e3 / 1.5);
  EXPECT_DOUBLE_EQ(r.joint_materials[0].normal_stiffness, m.joint_materials[0].normal_stiffness);
  EXPECT_DOUBLE_EQ(r.block_materials[0].young, m.block_materials[0].young);
  EXPECT_THROW((void)reduce_strength(m, joints_only, 0.0), std::invalid_argument);
}

}  // namespace
}  // namespace bimrock
