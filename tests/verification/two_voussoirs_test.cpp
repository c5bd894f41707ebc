// Verification: two leaning voussoirs on dry springings (cohesionless, tensionless joints), the
// smallest arch, under their own weight, for associated and non-associated flow.
//
// Each voussoir is the trapezoid between the lines x + y = 7.5 and x + y = 12.5 in its quadrant
// (a 2-voussoir arch of centre-line radius 10 m, t/R = 0.5); the crown joint is the segment
// x = 0, 7.5 <= y <= 12.5, the springings y = 0. Sources of the expected numbers (rigid-block
// limit analysis, Heyman's safe theorem, worked here):
//  - by symmetry the crown carries a horizontal thrust H and no shear; each springing carries
//    the weight W of its voussoir and H. Moments about the springing's reaction point x_s:
//    H = W (x_s - x_G) / y_c, with y_c the height of the thrust at the crown and x_G the
//    voussoir's centroid. The least thrust a statically admissible state can have puts y_c at
//    the crown's top (12.5) and x_s at the springing's inner end (7.5):
//    H_min / W = (7.5 - x_G) / 12.5, with x_G = (T(12.5) - T(7.5)) / A from the two right
//    triangles of legs a (area a^2/2, centroid a/3): x_G = 5.104 m, H_min / W = 0.1917.
//  - Sliding at the springings needs tan(phi) <= H / W. So for tan(phi) >= H_min / W (10.85 deg)
//    the thrust line of least thrust is statically admissible: with associated flow the arch
//    stands (safe theorem), and for tan(phi) < H_min / W no statically admissible state exists
//    at all, so it collapses whatever the flow rule.
//  - Non-associated flow (dilation psi < phi) has no safe theorem, but here the thrust can only
//    fall towards that least value: the springings slide only while H = W tan(phi), sliding
//    spreads the voussoirs, and spreading opens the crown at its bottom and the springings at
//    their outer ends until the arch is the three-hinge arch of least thrust, statically
//    determinate with H = H_min. Opening is the tension cut-off's own (associated) flow. So for
//    tan(phi) > H_min / W the arch comes to rest before or at that state whatever the dilation.
//    (Radenkovic's lower bound does not help here: for a joint the largest surface inside the
//    yield surface whose normals are the flows (tan(psi), +-1) has friction psi, which is below
//    10.85 deg for small dilations.)
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"
#include "support/degrees.hpp"

namespace bimrock {
namespace {

using testing::kDeg;

/// The least thrust ratio H_min / W (see the file comment).
double least_thrust_ratio() {
  const auto area = [](double a) { return a * a / 2.0; };
  const double centroid_x =
      (area(12.5) * 12.5 / 3.0 - area(7.5) * 7.5 / 3.0) / (area(12.5) - area(7.5));
  return (7.5 - centroid_x) / 12.5;
}

CaseSpec voussoirs(double friction_deg, double dilation_deg) {
  CaseSpec c;
  c.file = "voussoirs";
  c.settings.plane = PlaneMode::stress;
  c.block_materials = {testing::rock(1e10, 0.2, 20e3)};
  c.joint_materials = {testing::dry_joint("dry", 1e11, 4e10, friction_deg, dilation_deg)};
  c.blocks = testing::blocks_of({Polygon{{{7.5, 0}, {12.5, 0}, {0, 12.5}, {0, 7.5}}},
                                 Polygon{{{0, 7.5}, {0, 12.5}, {-12.5, 0}, {-7.5, 0}}}});
  c.default_joint = "dry";
  for (const double side : {1.0, -1.0})
    c.supports.push_back(testing::base_of({7.5 * side, 0}, {12.5 * side, 0}, "dry"));
  c.stages.push_back(testing::gravity_stage(4));
  return c;
}

TEST(TwoVoussoirs, LeastThrustNeedsTenPointEightFiveDegrees) {
  EXPECT_NEAR(std::atan(least_thrust_ratio()) / kDeg, 10.85, 0.005);
}

TEST(TwoVoussoirs, StandWithCohesionlessJointsForEveryFrictionFrom20AndEveryDilation) {
  for (int phi = 20; phi <= 80; phi += 5) {
    for (int psi = 0; psi <= phi; psi += 5) {
      ASSERT_GT(std::tan(phi * kDeg), least_thrust_ratio());  // the premise (file comment)
      const PlasticResult r = run_plastic_analysis(build_model(voussoirs(phi, psi)));
      EXPECT_FALSE(r.collapse.has_value()) << "phi " << phi << ", psi " << psi;
      EXPECT_FALSE(r.stopped.has_value())
          << "phi " << phi << ", psi " << psi << ": " << r.stopped->reason;
      EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12) << "phi " << phi << ", psi " << psi;
    }
  }
}

TEST(TwoVoussoirs, SlideApartBelowTheLeastThrustFrictionWhateverTheDilation) {
  ASSERT_LT(std::tan(10.0 * kDeg), least_thrust_ratio());
  for (int psi = 0; psi <= 10; ++psi) {
    const Model model = build_model(voussoirs(10.0, psi));
    const PlasticResult r = run_plastic_analysis(model);
    ASSERT_TRUE(r.collapse.has_value()) << "psi " << psi;
    EXPECT_FALSE(r.stopped.has_value()) << "psi " << psi;
    // No fraction of the weight is carried: unstable under the first load.
    EXPECT_TRUE(r.collapse->unstable_at_first_load) << "psi " << psi;
    EXPECT_EQ(r.collapse->carried, 0.0);
    EXPECT_LE(r.collapse->failed, PlasticOptions{}.bracket_tolerance);
    // The mechanism: the voussoirs slide apart at the springings (block 0 is the right one:
    // it moves right relative to block 1) and their weight does work (they sink).
    const Eigen::VectorXd& d = r.collapse->direction;
    ASSERT_EQ(d.size(), 12);
    EXPECT_GT(d(0) - d(6), 0.0) << "psi " << psi;
    EXPECT_LT(d(1) + d(7), 0.0) << "psi " << psi;
    bool slips_at_springing = false;
    for (const MechanismEntry& e : r.collapse->mechanism)
      slips_at_springing =
          slips_at_springing || (r.points[e.point].block_j == kGround && e.mode != kOpeningMode);
    EXPECT_TRUE(slips_at_springing) << "psi " << psi;
  }
}

}  // namespace
}  // namespace bimrock
