// Verification: a rigid-plastic block on an inclined plane, the classic friction and toppling
// problems. The slope is the x-axis and gravity is tilted by the slope angle theta, which is
// the same problem turned (exact). Joints: Mohr-Coulomb without cohesion, no tension.
//
// Sources of the expected numbers (statics of a block of weight W on a plane with friction phi):
//  - stable without push when theta < phi, slides when theta > phi;
//  - force parallel to the slope to push it up:  P = W (sin theta + cos theta tan phi),
//    to push it down: P = W (cos theta tan phi - sin theta);
//  - horizontal force to push it up: H = W tan(theta + phi), to pull it down: H = W tan(phi -
//  theta);
//  - a block of width b and height h topples when tan theta > b / h (resultant beyond the toe),
//    1 m x 2.5 m: atan(1 / 2.5) = 21.80 deg (docs/formulation.md: end-point yield checks);
//  - the 3DEC verification set "block on an inclined plane" (b = 10 m, rho = 2000 kg/m^3,
//    g = 10 m/s^2, k_n = k_s = 10 MPa/m, slope 40 deg): h = 10 m, phi = 40.1 deg stays;
//    h = 5 m, phi = 20 deg slides; h = 25 m, phi = 40 deg topples.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/incline_case.hpp"

namespace bimrock {
namespace {

using testing::Incline;
using testing::incline_case;
using testing::kDeg;

PlasticOptions precise() {
  PlasticOptions o;
  o.bracket_tolerance = 1e-8;
  o.max_bisections = 60;
  return o;
}

// The force factor at collapse of stage 2 (middle of the bracket), times |push|.
double collapse_force(const Incline& in, Vec2 push) {
  const PlasticResult r = run_plastic_analysis(build_model(incline_case(in, push)), precise());
  EXPECT_TRUE(r.collapse.has_value());
  if (!r.collapse)
    return 0.0;
  EXPECT_EQ(r.collapse->stage, 1);
  return 0.5 * (r.collapse->carried + r.collapse->failed) * push.norm();
}

TEST(BlockOnIncline, StandsBelowTheFrictionAngle) {
  Incline in;
  const PlasticResult r = run_plastic_analysis(build_model(incline_case(in)));
  EXPECT_FALSE(r.collapse.has_value());
  EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12);
}

TEST(BlockOnIncline, SlidesAboveTheFrictionAngle) {
  Incline in;
  in.slope_deg = 35.0;
  const PlasticResult r = run_plastic_analysis(build_model(incline_case(in)));
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_EQ(r.collapse->stage, 0);
  EXPECT_LT(r.collapse->failed, 1e-3);  // proportional gravity: no load can be carried
}

TEST(BlockOnIncline, ForceParallelToTheSlopeToPushItUpAndDown) {
  Incline in;
  const double t = in.slope_deg * kDeg;
  const double mu = std::tan(in.friction_deg * kDeg);
  const double up = in.weight() * (std::sin(t) + std::cos(t) * mu);
  const double down = in.weight() * (std::cos(t) * mu - std::sin(t));
  EXPECT_NEAR(collapse_force(in, Vec2(-2.0 * in.weight(), 0)), up, 1e-6 * up);
  EXPECT_NEAR(collapse_force(in, Vec2(2.0 * in.weight(), 0)), down, 1e-6 * down);
}

TEST(BlockOnIncline, HorizontalForceToPushItUpAndPullItDown) {
  Incline in;
  const double t = in.slope_deg * kDeg;
  const double phi = in.friction_deg * kDeg;
  const Vec2 horizontal(std::cos(t), std::sin(t));  // true horizontal, pointing downslope
  const double up = in.weight() * std::tan(t + phi);
  const double down = in.weight() * std::tan(phi - t);
  EXPECT_NEAR(collapse_force(in, -2.0 * in.weight() * horizontal), up, 1e-6 * up);
  EXPECT_NEAR(collapse_force(in, 2.0 * in.weight() * horizontal), down, 1e-6 * down);
}

bool topples(const PlasticResult& r) {
  // Toppling: the heel opens and nothing slips; sliding: something slips.
  bool opens = false;
  bool slips = false;
  for (const MechanismEntry& e : r.collapse->mechanism) {
    (e.mode == kOpeningMode ? opens : slips) = true;
  }
  return opens && !slips;
}

TEST(BlockOnIncline, TallBlockToppleAtExactlyAtanOfWidthOverHeight) {
  Incline in;
  in.width = 1.0;
  in.height = 2.5;
  in.friction_deg = 60.0;
  const double critical = std::atan(1.0 / 2.5) / kDeg;  // 21.80 deg
  in.slope_deg = critical - 0.05;
  EXPECT_FALSE(run_plastic_analysis(build_model(incline_case(in))).collapse.has_value());
  in.slope_deg = critical + 0.05;
  const PlasticResult r = run_plastic_analysis(build_model(incline_case(in)));
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_TRUE(topples(r));
}

// Dilation does not change any of these answers: one block's sliding or toppling is a unique
// mechanism, and nothing confines the block's dilatant lift off the plane, so the statics
// above hold for every dilation from 0 (non-associated) to the friction angle (associated).
TEST(BlockOnIncline, EveryDilationStandsBelowSlidesAboveAndNeedsTheSamePush) {
  for (const double psi : {0.0, 10.0, 20.0, 30.0}) {
    Incline in;
    in.dilation_deg = psi;
    EXPECT_FALSE(run_plastic_analysis(build_model(incline_case(in))).collapse) << psi;
    const double t = in.slope_deg * kDeg;
    const double mu = std::tan(in.friction_deg * kDeg);
    const double up = in.weight() * (std::sin(t) + std::cos(t) * mu);
    const double down = in.weight() * (std::cos(t) * mu - std::sin(t));
    EXPECT_NEAR(collapse_force(in, Vec2(-2.0 * in.weight(), 0)), up, 1e-6 * up) << psi;
    EXPECT_NEAR(collapse_force(in, Vec2(2.0 * in.weight(), 0)), down, 1e-6 * down) << psi;
    in.slope_deg = 35.0;
    const PlasticResult r = run_plastic_analysis(build_model(incline_case(in)));
    ASSERT_TRUE(r.collapse.has_value()) << psi;
    EXPECT_FALSE(topples(r)) << psi;
  }
}

TEST(BlockOnIncline, EveryDilationTopplesTheTallBlockAtAtanOfWidthOverHeight) {
  const double critical = std::atan(1.0 / 2.5) / kDeg;  // 21.80 deg
  for (const double psi : {0.0, 20.0, 40.0, 60.0}) {
    Incline in;
    in.width = 1.0;
    in.height = 2.5;
    in.friction_deg = 60.0;
    in.dilation_deg = psi;
    in.slope_deg = critical - 0.05;
    EXPECT_FALSE(run_plastic_analysis(build_model(incline_case(in))).collapse) << psi;
    in.slope_deg = critical + 0.05;
    const PlasticResult r = run_plastic_analysis(build_model(incline_case(in)));
    ASSERT_TRUE(r.collapse.has_value()) << psi;
    EXPECT_TRUE(topples(r)) << psi;
  }
}

Incline three_dec(double height, double friction_deg) {
  Incline in;
  in.width = 10.0;
  in.height = height;
  in.slope_deg = 40.0;
  in.friction_deg = friction_deg;
  in.unit_weight = 2000.0 * 10.0;
  in.k = 10e6;
  return in;
}

TEST(BlockOnIncline, ThreeDecSetStays) {
  EXPECT_FALSE(run_plastic_analysis(build_model(incline_case(three_dec(10.0, 40.1)))).collapse);
}

TEST(BlockOnIncline, ThreeDecSetSlides) {
  const PlasticResult r = run_plastic_analysis(build_model(incline_case(three_dec(5.0, 20.0))));
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_FALSE(topples(r));
}

TEST(BlockOnIncline, ThreeDecSetTopples) {
  const PlasticResult r = run_plastic_analysis(build_model(incline_case(three_dec(25.0, 40.0))));
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_TRUE(topples(r));
}

}  // namespace
}  // namespace bimrock
