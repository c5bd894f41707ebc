// Verification: the paper's example 2, a jointed rock mass under gravity and a point load P at A.
//
// Source of the expected number: the paper (and plasticity theory) give collapse at P = 2C:
// the loaded 1 m half-brick is sheared out along its two 1 m joints of cohesion c = 20 kPa
// (friction 0, no tension), P = 2 x 20 kPa x 1 m x 1 m = 40 kN. The paper also claims the
// answer does not depend on the step size: increments of 2, 5 and 10 kN must all find it.
//
// Geometry (the paper's figure is lost; examples/pull_out/README.md): a brick wall of 2.0 m x
// 0.5 m bricks, 3 bricks long and 4 rows high, on a fixed elastic base; horizontal joints
// continuous, the vertical joints of rows 1 and 3 shifted by 1 m, so those rows end in 1 m
// half-bricks; P pulls horizontally outward at A = (6.0, 0.75).
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

CaseSpec pull_out_case(double increment_kn) {
  CaseSpec c;
  c.file = "pull_out";
  c.block_materials = {testing::rock(89e9, 0.26, 16e3)};
  JointStrength cohesive;
  cohesive.cohesion = Softening::constant(20e3);
  JointMaterial vertical = testing::springs("vertical", 395.9e9, 438.8e9);
  JointMaterial horizontal = testing::springs("horizontal", 531.9e9, 438.8e9);
  vertical.strength = horizontal.strength = cohesive;
  JointMaterial base = testing::springs("base", 531.9e9, 438.8e9);  // elastic
  c.joint_materials = {vertical, horizontal, base};
  c.blocks = testing::blocks_of(brick_pattern(3, 4, 2.0, 0.5, Stagger::rows));
  c.default_joint = "vertical";
  c.joint_rules.push_back({testing::with_orientation(0.0), "horizontal", {0, "rule"}});
  SupportSpec support = testing::fixed({0, 0}, {6, 0});
  support.joint_material = "base";
  c.supports.push_back(support);
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "gravity"}};
  gravity.loads.gravity = Vec2(0, -1);
  const double total = 60e3;
  StageSpec pull{
      "pull", {}, static_cast<int>(total / (increment_kn * 1e3) + 0.5), std::nullopt, {0, "pull"}};
  pull.loads.points.push_back({Vec2(6.0, 0.75), Vec2(total, 0.0), {0, "P"}});
  c.stages = {gravity, pull};
  c.monitors.push_back({"A", Vec2(6.0, 0.75), {0, "A"}});
  return c;
}

class PullOut : public ::testing::TestWithParam<double> {};

TEST_P(PullOut, CollapsesAtTwiceTheJointCohesionForAnyStepSize) {
  PlasticOptions o;
  o.bracket_tolerance = 1e-5;
  const PlasticResult r = run_plastic_analysis(build_model(pull_out_case(GetParam())), o);
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_EQ(r.collapse->stage, 1);
  const double carried = r.collapse->carried * 60e3;
  const double failed = r.collapse->failed * 60e3;
  std::printf("increment %4.1f kN: collapse bracket [%.4f, %.4f] kN after %zu increments\n",
              GetParam(), carried / 1e3, failed / 1e3, r.history.size());
  EXPECT_NEAR(carried, 40e3, 40.0);  // 0.1%
  EXPECT_NEAR(failed, 40e3, 40.0);
}

INSTANTIATE_TEST_SUITE_P(StepSizes, PullOut, ::testing::Values(2.0, 5.0, 10.0));

}  // namespace
}  // namespace bimrock
