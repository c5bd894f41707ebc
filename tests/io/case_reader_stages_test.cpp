// The nonlinear part of the case file: strength laws and load stages. Expected values are unit
// conversions worked by hand (tan 30 deg = 0.57735..., sin 30 deg = 0.5).
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/io/case_reader.hpp>

#include "support/read_error.hpp"

namespace bimrock {
namespace {

const std::string kStrengthCase = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2, strength: {cohesion: 1.0e6, friction: 30, planes: 12}}
  clay: {E: 1.0e9, nu: 0.3, strength: {criterion: tresca, cohesion: 5.0e4}}
joint_materials:
  joint: {kn: 1.0e10, ks: 1.0e10, cohesion: 2.0e4, friction: 30, dilation: 10, tensile_strength: 1.0e3,
          residual_cohesion: 0, softening_slip: 0.01}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
monitors:
  - {name: A, at: [1, 1]}
)";

using testing::read_error_of;

TEST(CaseReaderStages, ReadsJointAndBlockStrengthInDegrees) {
  const Case c = read_case_string(kStrengthCase, "case.yaml");
  const BlockMaterial& rock = c.spec.block_materials[0];
  ASSERT_TRUE(rock.strength.has_value());
  EXPECT_DOUBLE_EQ(rock.strength->cohesion, 1e6);
  EXPECT_NEAR(rock.strength->friction, 0.5, 1e-15);  // sin 30 deg
  EXPECT_NEAR(rock.strength->dilation, 0.5, 1e-15);  // associated by default
  EXPECT_EQ(rock.strength->planes, 12);
  EXPECT_EQ(c.spec.block_materials[1].strength->criterion, BlockStrength::Criterion::tresca);
  const JointStrength& j = *c.spec.joint_materials[0].strength;
  EXPECT_NEAR(j.friction.peak, 1.0 / std::sqrt(3.0), 1e-15);  // tan 30 deg
  EXPECT_NEAR(j.dilation, std::tan(10.0 * M_PI / 180.0), 1e-15);
  EXPECT_DOUBLE_EQ(j.cohesion.peak, 2e4);
  EXPECT_DOUBLE_EQ(j.cohesion.residual, 0.0);
  EXPECT_DOUBLE_EQ(j.cohesion.distance, 0.01);
  EXPECT_DOUBLE_EQ(j.tensile.value(1.0), 1e3);  // no softening given: constant
}

TEST(CaseReaderStages, ReadsStagesWithLoadAndDisplacementControl) {
  const Case c = read_case_string(kStrengthCase + R"(stages:
  - name: gravity
    loads: {gravity: [0, -1]}
  - name: push
    increments: 20
    control: {monitor: A, direction: [1, 0], displacement: 0.01}
    loads:
      points:
        - {at: [1, 1], force: [1000, 0]}
)",
                                  "case.yaml");
  ASSERT_EQ(c.spec.stages.size(), 2u);
  EXPECT_EQ(c.spec.stages[0].increments, 1);
  EXPECT_EQ(c.spec.stages[0].loads.gravity, Vec2(0, -1));
  EXPECT_EQ(c.spec.stages[1].increments, 20);
  ASSERT_TRUE(c.spec.stages[1].control.has_value());
  EXPECT_EQ(c.spec.stages[1].control->monitor, "A");
  EXPECT_DOUBLE_EQ(c.spec.stages[1].control->displacement, 0.01);
  EXPECT_EQ(c.spec.stages[1].source.line, 15);  // kStrengthCase is 11 lines
}

TEST(CaseReaderStages, RejectsLoadsAndStagesTogether) {
  EXPECT_NE(read_error_of(kStrengthCase + "loads: {gravity: [0, -1]}\nstages:\n  - {name: s}\n")
                .find("case.yaml:12: loads: give loads either here"),
            std::string::npos);
}

TEST(CaseReaderStages, RejectsAResidualWithoutASofteningDistance) {
  std::string text = kStrengthCase;
  text.replace(text.find(", softening_slip: 0.01"), 21, "");
  EXPECT_NE(read_error_of(text).find("residual_cohesion: needs softening_slip"), std::string::npos)
      << read_error_of(text);
}

TEST(CaseReaderStages, RejectsAFrictionAngleOf90Degrees) {
  std::string text = kStrengthCase;
  text.replace(text.find("friction: 30, dilation"), 12, "friction: 90");
  EXPECT_NE(read_error_of(text).find("joint_materials.joint.friction: must be an angle"),
            std::string::npos)
      << read_error_of(text);
}

TEST(CaseReaderStages, RejectsStrengthOnAContinuumInterface) {
  const std::string text = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2}
joint_materials:
  glue: {continuum: true, cohesion: 1.0}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
)";
  EXPECT_NE(read_error_of(text).find(
                "case.yaml:5: joint_materials.glue: a continuum interface has no strength"),
            std::string::npos)
      << read_error_of(text);
}

TEST(CaseReaderStages, RejectsAnUnknownControlKey) {
  EXPECT_NE(
      read_error_of(
          kStrengthCase +
          "stages:\n  - name: s\n    control: {monitor: A, direction: [1, 0], displacment: 1}\n")
          .find("case.yaml:14:"),
      std::string::npos);
}

}  // namespace
}  // namespace bimrock
