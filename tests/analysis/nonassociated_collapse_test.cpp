// The paper's example 2 (pull-out of a half-brick, Zhang & Lu) with cohesive and frictional
// joints: whatever the dilation, from 0 to the friction angle, the analysis ends with a proven
// collapse (a bracket and a mechanism), never stopped. The collapse load itself is checked
// against independent numbers in tests/verification/; here the point is that the complete LCP
// method decides every increment of non-associated flow, including the degenerate ones of
// dilation 0 (opposite slip flows) on which Lemke's method ends on rays that prove nothing.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/pull_out_case.hpp"

namespace bimrock {
namespace {

CaseSpec pull_out_case(double friction_deg, double dilation_deg) {
  JointStrength s;
  s.cohesion = Softening::constant(20e3);
  s.friction = Softening::constant(std::tan(friction_deg * M_PI / 180.0));
  s.dilation = std::tan(dilation_deg * M_PI / 180.0);
  return testing::pull_out_case(s, 120e3, 30);
}

TEST(NonAssociatedCollapse, PullOutEndsWithAProvenCollapseForEveryDilation) {
  for (const double psi : {0.0, 10.0, 20.0, 30.0}) {
    const PlasticResult r = run_plastic_analysis(build_model(pull_out_case(30.0, psi)));
    ASSERT_TRUE(r.collapse.has_value()) << "psi " << psi;
    EXPECT_FALSE(r.stopped.has_value()) << "psi " << psi;
    EXPECT_EQ(r.collapse->stage, 1);
    EXPECT_LT(r.collapse->carried, r.collapse->failed);
    EXPECT_LE(r.collapse->failed - r.collapse->carried,
              2.0 * PlasticOptions{}.bracket_tolerance * r.collapse->failed);
    EXPECT_FALSE(r.collapse->mechanism.empty()) << "psi " << psi;
    EXPECT_FALSE(r.collapse->unstable_at_first_load);
    // Above the cohesion-only collapse, P = 2 c (40 kN; friction only adds strength), and
    // within the stage's 120 kN.
    EXPECT_GT(r.collapse->carried * 120e3, 40e3) << "psi " << psi;
  }
}

}  // namespace
}  // namespace bimrock
