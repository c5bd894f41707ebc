// Verification: the factor of safety by strength reduction of a block on an inclined plane.
//
// Source of the expected numbers: limit equilibrium of a rigid block sliding on a plane, exact
// for this mechanism (the block is wide and low, so it slides before it could topple). With the
// strengths divided by F the block slides when the shear it carries, W sin(alpha), equals the
// reduced strength of its base, (c L + W cos(alpha) tan(phi)) / F:
//     F = (c L + W cos(alpha) tan(phi)) / (W sin(alpha)),
// which is tan(phi) / tan(alpha) without cohesion. The bracket [lower, upper] must hold F and be
// as narrow as asked; a block on a level plane carries no shear and is stable for every F.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/model/model.hpp>

#include "support/incline_case.hpp"

namespace bimrock {
namespace {

using testing::Incline;
using testing::kDeg;

PlasticResult with_factor_of_safety(const CaseSpec& c, double largest = 10.0) {
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  options.factor_of_safety->largest = largest;
  return run_plastic_analysis(build_model(c), options);
}

void expect_bracket(const PlasticResult& r, double expected) {
  ASSERT_FALSE(r.collapse.has_value());
  ASSERT_TRUE(r.factor_of_safety.has_value());
  const FactorOfSafety& f = *r.factor_of_safety;
  ASSERT_TRUE(f.collapse.has_value());
  std::printf("F in [%.6f, %.6f], expected %.6f\n", f.lower, f.collapse->failed, expected);
  EXPECT_LE(f.lower, expected * (1.0 + 1e-6));
  EXPECT_GE(f.collapse->failed, expected * (1.0 - 1e-6));
  EXPECT_LE(f.collapse->failed - f.lower, 1.1e-3 * f.collapse->failed);
  EXPECT_FALSE(f.collapse->mechanism.empty());
  EXPECT_GT(f.trials.size(), 2u);
}

TEST(FactorOfSafety, CohesionlessBlockOnAnInclineIsTanPhiOverTanAlpha) {
  Incline in;
  in.slope_deg = 20.0;
  in.friction_deg = 35.0;
  expect_bracket(with_factor_of_safety(testing::incline_case(in)),
                 std::tan(35.0 * kDeg) / std::tan(20.0 * kDeg));
}

// A block on a 30 degree incline, its joint of 20 degrees friction and 5 kPa cohesion, and its F
// by limit equilibrium.
constexpr double kInclineCohesion = 5e3;  // [Pa]

Incline cohesive_incline() {
  Incline in;
  in.slope_deg = 30.0;
  in.friction_deg = 20.0;
  return in;
}

CaseSpec cohesive_incline_case(const Incline& in) {
  CaseSpec c = testing::incline_case(in);
  c.joint_materials[0].strength->cohesion = Softening::constant(kInclineCohesion);
  return c;
}

double cohesive_incline_factor(const Incline& in) {
  const double w = in.weight();
  const double a = in.slope_deg * kDeg;
  return (kInclineCohesion * in.width + w * std::cos(a) * std::tan(in.friction_deg * kDeg)) /
         (w * std::sin(a));
}

TEST(FactorOfSafety, CohesiveBlockOnAnInclineFollowsLimitEquilibrium) {
  const Incline in = cohesive_incline();
  expect_bracket(with_factor_of_safety(cohesive_incline_case(in)), cohesive_incline_factor(in));
}

TEST(FactorOfSafety, ABlockOnALevelPlaneIsStableForEveryFactor) {
  Incline in;
  in.slope_deg = 0.0;
  const PlasticResult r = with_factor_of_safety(testing::incline_case(in), 3.0);
  ASSERT_TRUE(r.factor_of_safety.has_value());
  EXPECT_FALSE(r.factor_of_safety->collapse.has_value());
  EXPECT_FALSE(r.factor_of_safety->undecided);
  EXPECT_NEAR(r.factor_of_safety->lower, 3.0, 1e-12);
}

// A pseudo-static earthquake on a block on a level joint (cohesionless, phi): the horizontal
// inertial force kh W is resisted by (1 + kv) W tan(phi) (kv downwards), so
// F = (1 + kv) tan(phi) / kh (limit equilibrium of a sliding block).
TEST(FactorOfSafety, SeismicLoadOnALevelBlockFollowsLimitEquilibrium) {
  Incline in;
  in.slope_deg = 0.0;
  in.friction_deg = 30.0;
  CaseSpec c = testing::incline_case(in);
  const double kh = 0.2, kv = 0.1;
  StageSpec quake{"earthquake", {}, 4, std::nullopt, {0, "stages[1]"}};
  quake.loads.gravity = Vec2(kh, -kv);  // what loads.seismic {kh, kv} adds (case_loading.cpp)
  c.stages.push_back(quake);
  expect_bracket(with_factor_of_safety(c), (1.0 + kv) * std::tan(30.0 * kDeg) / kh);
}

// F after a stage that is not the last: the block's F under gravity alone, tan(phi) /
// tan(alpha), although a later stage pushes it downslope; the later stage still runs.
TEST(FactorOfSafety, AfterAGivenStageTheLaterStagesStillRun) {
  Incline in;
  in.slope_deg = 20.0;
  in.friction_deg = 35.0;
  const double push = 0.2 * in.weight();  // downslope, well below what it takes to slide
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  options.factor_of_safety->after_stage = 0;
  const PlasticResult r =
      run_plastic_analysis(build_model(testing::incline_case(in, Vec2(push, 0.0), 2)), options);
  EXPECT_FALSE(r.collapse.has_value());
  ASSERT_FALSE(r.history.empty());
  EXPECT_EQ(r.history.back().stage, 1);
  EXPECT_DOUBLE_EQ(r.history.back().stage_factor, 1.0);
  expect_bracket(r, std::tan(35.0 * kDeg) / std::tan(20.0 * kDeg));
  EXPECT_EQ(r.factor_of_safety->stage, 0);
}

// A block on an incline steeper than its friction angle slides under its own weight: F < 1.
// Each trial runs the gravity stage again with the strengths raised (divided by F < 1); the
// same limit equilibrium gives F = tan(phi) / tan(alpha) = tan(30) / tan(35) = 0.8245, and with
// cohesion F = (c L + W cos(alpha) tan(phi)) / (W sin(alpha)).
TEST(FactorOfSafety, ABlockThatSlidesUnderItsStagesHasAFactorBelowOne) {
  Incline in;
  in.slope_deg = 35.0;
  in.friction_deg = 30.0;
  CaseSpec c = testing::incline_case(in);
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  const PlasticResult r = run_plastic_analysis(build_model(c), options);
  ASSERT_TRUE(r.collapse.has_value());  // the stages collapse, as F < 1 says
  ASSERT_TRUE(r.factor_of_safety.has_value());
  const FactorOfSafety& f = *r.factor_of_safety;
  ASSERT_TRUE(f.collapse.has_value());
  const double expected = std::tan(30.0 * kDeg) / std::tan(35.0 * kDeg);
  EXPECT_LE(f.lower, expected * (1.0 + 1e-6));
  EXPECT_GE(f.collapse->failed, expected * (1.0 - 1e-6));
  EXPECT_LE(f.collapse->failed - f.lower, 1.1e-3 * f.collapse->failed);
  EXPECT_FALSE(f.collapse->mechanism.empty());
  ASSERT_FALSE(f.trials.empty());
  EXPECT_DOUBLE_EQ(f.trials.back().factor, f.lower);

  const double cohesion = 1e3;  // [Pa]
  c.joint_materials[0].strength->cohesion = Softening::constant(cohesion);
  const double w = in.weight(), a = in.slope_deg * kDeg;
  const double with_cohesion =
      (cohesion * in.width + w * std::cos(a) * std::tan(in.friction_deg * kDeg)) /
      (w * std::sin(a));
  ASSERT_LT(with_cohesion, 1.0);
  const PlasticResult rc = run_plastic_analysis(build_model(c), options);
  ASSERT_TRUE(rc.factor_of_safety && rc.factor_of_safety->collapse);
  EXPECT_LE(rc.factor_of_safety->lower, with_cohesion * (1.0 + 1e-6));
  EXPECT_GE(rc.factor_of_safety->collapse->failed, with_cohesion * (1.0 - 1e-6));
}

// The cohesive block, (a) from an initial stress (uniform, within the joint's strength, not
// traction-free on the block's faces: the first stage applies the difference), and (b) propped
// downslope by a second block that a later stage excavates. Limit equilibrium does not depend on
// the stress the rock started from (the first stage ends in equilibrium with the same loads),
// nor on a prop that is gone: F after the last stage is the lone block's.
TEST(FactorOfSafety, FromAnInitialStressTheBlockFollowsLimitEquilibrium) {
  const Incline in = cohesive_incline();
  CaseSpec c = cohesive_incline_case(in);
  InitialStressSpec field;
  field.uniform = Eigen::Vector3d(-1e4, -2e4, 3e3);  // [Pa]: |tau| < c + 2e4 tan(20 deg)
  c.initial_stress = field;
  const PlasticResult r = with_factor_of_safety(c);
  ASSERT_TRUE(r.initial_stress.has_value());
  EXPECT_GT(r.initial_stress->residual, 0.0);  // the field is not the block's equilibrium
  expect_bracket(r, cohesive_incline_factor(in));
}

TEST(FactorOfSafety, AfterAnExcavationTheBlockLeftFollowsLimitEquilibrium) {
  const Incline in = cohesive_incline();
  CaseSpec c = cohesive_incline_case(in);
  // The prop [w, w + 0.5] x [0, h], downslope, on the same base.
  c.blocks.push_back(testing::blocks_of({Polygon{{{in.width, 0},
                                                  {in.width + 0.5, 0},
                                                  {in.width + 0.5, in.height},
                                                  {in.width, in.height}}}})
                         .front());
  StageSpec excavation{"remove the prop", {}, 2, std::nullopt, {0, "stages[1]"}};
  BlockSelector prop;
  prop.kind = BlockSelector::Kind::box;
  prop.box = BBox{Vec2(in.width + 0.1, 0.1), Vec2(in.width + 0.4, in.height - 0.1)};
  prop.source = {0, "stages[1].excavate"};
  excavation.excavate = prop;
  c.stages.push_back(excavation);
  const PlasticResult r = with_factor_of_safety(c);
  EXPECT_EQ(r.factor_of_safety->stage, 1);
  expect_bracket(r, cohesive_incline_factor(in));
}

}  // namespace
}  // namespace bimrock
