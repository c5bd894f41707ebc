// Verification: plastic flow of a sliding joint under displacement control.
// A block [0, 2] x [0, 0.5] on a fixed base, pushed sideways at the level of the joint (so no
// moment tilts it) by a prescribed displacement of the point (1, 0.001). Springs and rock are
// made very stiff (1e13) so that the elastic displacements (~1e-8 m) vanish beside the slip
// (~1e-3 m); the expected numbers are then those of rigid-plastic sliding:
//  - dilation (non-associated flow when psi != phi): the block rises by tan(psi) per unit of
//    slip, whatever the friction (flow rule d delta_p = lambda [tan psi, 1]);
//  - softening: the force needed to slide is the joint's strength times its length,
//    H = c(kappa) L t, with c falling linearly from c_peak to c_res over a slip s_r.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr double kStiff = 1e13;
constexpr double kLength = 2.0;

CaseSpec sliding_block(const JointStrength& strength, double displacement, int increments) {
  CaseSpec c;
  c.file = "slide";
  c.block_materials = {testing::rock(kStiff, 0.2, 50e3)};
  JointMaterial joint = testing::springs("joint", kStiff, kStiff);
  joint.strength = strength;
  c.joint_materials = {joint};
  c.blocks = testing::blocks_of({Polygon{{{-1, -1}, {3, -1}, {3, 0}, {-1, 0}}},
                                 Polygon{{{0, 0}, {kLength, 0}, {kLength, 0.5}, {0, 0.5}}}});
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({-1, -1}, {3, -1}));
  c.monitors.push_back({"P", Vec2(1.0, 0.001), {0, "P"}});
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "gravity"}};
  gravity.loads.gravity = Vec2(0, -1);
  StageSpec push{"push",
                 {},
                 increments,
                 DisplacementControlSpec{"P", Vec2(1, 0), displacement, {}},
                 {0, "push"}};
  push.loads.points.push_back({Vec2(1.0, 0.001), Vec2(1.0, 0.0), {0, "H"}});  // 1 N reference
  c.stages = {gravity, push};
  return c;
}

Vec2 final_displacement(const PlasticResult& r) {
  return r.history.back().monitors[0];
}

TEST(JointFlow, DilationLiftsTheBlockByTanPsiPerUnitSlip) {
  const double slide = 0.01;
  for (double psi_deg : {0.0, 10.0, 30.0}) {
    JointStrength s;
    s.friction = Softening::constant(std::tan(30.0 * M_PI / 180.0));
    s.dilation = std::tan(psi_deg * M_PI / 180.0);
    const PlasticResult r = run_plastic_analysis(build_model(sliding_block(s, slide, 10)));
    ASSERT_FALSE(r.collapse.has_value()) << psi_deg;
    const Vec2 u = final_displacement(r);
    EXPECT_NEAR(u.x(), slide, 1e-9);
    // Uplift relative to the end of the gravity stage (the block first settled elastically).
    const double settled = r.history.front().monitors[0].y();
    EXPECT_NEAR(u.y() - settled, std::tan(psi_deg * M_PI / 180.0) * slide, 1e-6 * slide) << psi_deg;
  }
}

TEST(JointFlow, DilationDoesNotChangeTheSlidingForce) {
  // With the normal force fixed by equilibrium, H = W tan(phi) for any psi.
  const double weight = 50e3 * kLength * 0.5;
  for (double psi_deg : {0.0, 30.0}) {
    JointStrength s;
    s.friction = Softening::constant(std::tan(30.0 * M_PI / 180.0));
    s.dilation = std::tan(psi_deg * M_PI / 180.0);
    const PlasticResult r = run_plastic_analysis(build_model(sliding_block(s, 0.01, 10)));
    EXPECT_NEAR(r.history.back().stage_factor, weight * std::tan(30.0 * M_PI / 180.0),
                1e-6 * weight);
  }
}

TEST(JointFlow, SofteningCohesionGivesAPeakThenTheResidualStrength) {
  const double c_peak = 40e3;
  const double c_res = 10e3;
  const double s_r = 0.002;
  JointStrength s;
  s.cohesion = {c_peak, c_res, s_r};
  const int increments = 16;
  const double total = 0.004;
  const PlasticResult r = run_plastic_analysis(build_model(sliding_block(s, total, increments)));
  ASSERT_FALSE(r.collapse.has_value());
  double peak = 0.0;
  for (const IncrementRecord& rec : r.history) {
    if (rec.stage != 1)
      continue;
    const double slip = rec.monitors[0].x();  // elastic part ~1e-8 m
    const double c = slip >= s_r ? c_res : c_peak + (c_res - c_peak) * slip / s_r;
    EXPECT_NEAR(rec.stage_factor, c * kLength, 1e-4 * c_peak * kLength) << "slip " << slip;
    peak = std::max(peak, rec.stage_factor);
  }
  // The peak c_peak L is reached as sliding starts, inside the first step; no step exceeds it.
  EXPECT_LE(peak, c_peak * kLength * (1.0 + 1e-6));
  EXPECT_NEAR(r.history.back().stage_factor, c_res * kLength, 1e-4 * c_res * kLength);
}

}  // namespace
}  // namespace bimrock
