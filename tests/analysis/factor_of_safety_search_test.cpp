// The factor of safety of a structure is a limit state: it does not depend on the joints'
// stiffness nor on how the stages were stepped. Two analyses of the same cohesive block on an
// incline, joint stiffnesses a decade apart and the gravity stage in 1 or 7 increments, must
// give overlapping brackets (each as narrow as its tolerance).
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/incline_case.hpp"

namespace bimrock {
namespace {

FactorOfSafety factor_of(double stiffness, int increments) {
  testing::Incline in;
  in.slope_deg = 30.0;
  in.friction_deg = 20.0;
  in.k = stiffness;
  CaseSpec c = testing::incline_case(in);
  c.joint_materials[0].strength->cohesion = Softening::constant(5e3);
  c.stages[0].increments = increments;
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  const PlasticResult r = run_plastic_analysis(build_model(c), options);
  EXPECT_TRUE(r.factor_of_safety && r.factor_of_safety->collapse);
  return *r.factor_of_safety;
}

TEST(FactorOfSafetySearch, DoesNotDependOnTheJointStiffnessNorOnTheStageIncrements) {
  const FactorOfSafety base = factor_of(1e9, 1);
  for (const FactorOfSafety& other : {factor_of(1e10, 1), factor_of(1e9, 7)}) {
    ASSERT_TRUE(other.collapse.has_value());
    EXPECT_LE(other.lower, base.collapse->failed);
    EXPECT_LE(base.lower, other.collapse->failed);
  }
}

}  // namespace
}  // namespace bimrock
