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
#include "support/pull_out_case.hpp"

namespace bimrock {
namespace {

CaseSpec pull_out_case(double increment_kn) {
  JointStrength cohesive;
  cohesive.cohesion = Softening::constant(20e3);
  const double total = 60e3;
  return testing::pull_out_case(cohesive, total,
                                static_cast<int>(total / (increment_kn * 1e3) + 0.5));
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
