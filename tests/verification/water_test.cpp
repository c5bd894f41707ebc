// Verification: water in the joints, against limit equilibrium of rigid blocks.
//
// Sources of the expected numbers:
//  - a block on an inclined joint with cohesion c and friction phi and a uniform uplift U on its
//    base (limit equilibrium of a sliding block, e.g. Wyllie & Mah, Rock Slope Engineering,
//    4th ed., 2004, section 6.2):  F = (c L + (W cos(alpha) - U) tan(phi)) / (W sin(alpha));
//  - a block on a level joint under a phreatic surface, pushed sideways: the joint's sliding
//    resistance falls with the pore pressure p on it to (W - p L) tan(phi); fully submerged, the
//    block bears on its joint with its buoyant weight (gamma - gamma_w) V (Archimedes);
//  - plane failure with a water-filled tension crack (Hoek & Bray, Rock Slope Engineering, 3rd
//    ed., 1981, chapter 7; Wyllie & Mah 2004, eqs. 6.3-6.7):
//      F = (c A + (W cos(psi_p) - U - V sin(psi_p)) tan(phi)) / (W sin(psi_p) + V cos(psi_p)),
//      A = (H - z) / sin(psi_p), U = gamma_w z_w A / 2, V = gamma_w z_w^2 / 2,
//      W = gamma_r H^2 ((1 - (z / H)^2) cot(psi_p) - cot(psi_f)) / 2 (crack in the upper surface).
// The model's joint springs carry the effective stress; the water acts on the block faces.
// Units: SI.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/incline_case.hpp"

namespace bimrock {
namespace {

using testing::Incline;
using testing::kDeg;

constexpr double kWater = 9810.0;  // [N/m^3]

// The factor of safety's bracket, to a relative width of 1e-7.
FactorOfSafety factor_of_safety(const CaseSpec& c) {
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  options.factor_of_safety->tolerance = 1e-7;
  const PlasticResult r = run_plastic_analysis(build_model(c), options);
  EXPECT_FALSE(r.collapse.has_value());
  EXPECT_TRUE(r.factor_of_safety.has_value());
  EXPECT_TRUE(r.factor_of_safety && r.factor_of_safety->collapse.has_value());
  return r.factor_of_safety.value_or(FactorOfSafety{});
}

void expect_factor(const FactorOfSafety& f, double expected, double relative) {
  ASSERT_TRUE(f.collapse.has_value());
  std::printf("F in [%.8f, %.8f], expected %.8f\n", f.lower, f.collapse->failed, expected);
  EXPECT_NEAR(f.lower, expected, relative * expected);
  EXPECT_NEAR(f.collapse->failed, expected, relative * expected);
}

WaterSpec uniform_pressure(Vec2 from, Vec2 to, double p) {
  WaterSpec w;
  w.lines.push_back({from, to, p, p, {0, "loads.water.lines[0]"}});
  return w;
}

TEST(Water, UpliftOnAnInclinedJointFollowsLimitEquilibrium) {
  Incline in;
  in.slope_deg = 30.0;
  in.friction_deg = 35.0;
  const double c = 4e3, u = 2e3;  // cohesion, uplift pressure [Pa]
  CaseSpec dry = testing::incline_case(in);
  dry.joint_materials[0].strength->cohesion = Softening::constant(c);
  CaseSpec wet = dry;
  wet.stages[0].loads.water = uniform_pressure({0, 0}, {in.width, 0}, u);
  const double w = in.weight(), a = in.slope_deg * kDeg, tan_phi = std::tan(in.friction_deg * kDeg);
  const double uplift = u * in.width;
  expect_factor(factor_of_safety(dry),
                (c * in.width + w * std::cos(a) * tan_phi) / (w * std::sin(a)), 1e-6);
  expect_factor(factor_of_safety(wet),
                (c * in.width + (w * std::cos(a) - uplift) * tan_phi) / (w * std::sin(a)), 1e-6);
}

// The level block [0, 2] x [0, 0.5] pushed along +x; the phreatic surface level at `level`.
double push_to_collapse(double level) {
  Incline in;
  in.slope_deg = 0.0;
  in.friction_deg = 30.0;
  CaseSpec spec = testing::incline_case(in, Vec2(1e4, 0.0));
  WaterSpec w;
  w.surface = {{-10.0, level}, {10.0, level}};
  spec.stages[0].loads.water = w;
  PlasticOptions o;
  o.bracket_tolerance = 1e-9;
  o.max_bisections = 60;
  const PlasticResult r = run_plastic_analysis(build_model(spec), o);
  EXPECT_TRUE(r.collapse.has_value());
  if (!r.collapse)
    return 0.0;
  EXPECT_EQ(r.collapse->stage, 1);
  return 0.5 * (r.collapse->carried + r.collapse->failed) * 1e4;
}

TEST(Water, PorePressureOnALevelJointLowersItsSlidingResistance) {
  Incline in;  // the block of push_to_collapse: 2 m x 0.5 m, 20 kN/m^3
  const double tan_phi = std::tan(30.0 * kDeg);
  const double level = 0.3;  // [m] above the joint: p = 0.3 gamma_w on it
  const double p = kWater * level;
  EXPECT_NEAR(push_to_collapse(level), (in.weight() - p * in.width) * tan_phi,
              1e-6 * in.weight() * tan_phi);
}

TEST(Water, ASubmergedBlockBearsItsBuoyantWeight) {
  Incline in;
  const double tan_phi = std::tan(30.0 * kDeg);
  const double volume = in.width * in.height;
  EXPECT_NEAR(push_to_collapse(1.0), (in.unit_weight - kWater) * volume * tan_phi,
              1e-6 * in.weight() * tan_phi);
}

// Hoek & Bray's plane failure: H = 20 m, face 60 deg, sliding plane 30 deg daylighting at the
// toe (0, 0), a vertical tension crack z = 6 m deep in the level upper surface; c = 20 kPa,
// phi = 35 deg, gamma_r = 25 kN/m^3. The sliding block alone, its base a support with the
// joint's strength; water in the crack to depth z_w (pressure line, triangular) and the uplift
// along the base falling linearly from the crack's foot to the toe (pressure line).
struct PlaneFailure {
  double height = 20.0, face_deg = 60.0, plane_deg = 30.0, crack = 6.0;
  double cohesion = 20e3, friction_deg = 35.0, unit_weight = 25e3;

  [[nodiscard]] Vec2 crack_foot() const {
    return {(height - crack) / std::tan(plane_deg * kDeg), height - crack};
  }
  [[nodiscard]] double expected(double water_depth) const {
    const double pp = plane_deg * kDeg, pf = face_deg * kDeg, r = crack / height;
    const double w =
        0.5 * unit_weight * height * height * ((1.0 - r * r) / std::tan(pp) - 1.0 / std::tan(pf));
    const double a = (height - crack) / std::sin(pp);
    const double u = 0.5 * kWater * water_depth * a;
    const double v = 0.5 * kWater * water_depth * water_depth;
    return (cohesion * a +
            (w * std::cos(pp) - u - v * std::sin(pp)) * std::tan(friction_deg * kDeg)) /
           (w * std::sin(pp) + v * std::cos(pp));
  }
  [[nodiscard]] CaseSpec spec(double water_depth) const {
    CaseSpec c;
    c.file = "plane_failure";
    c.block_materials = {testing::rock(20e9, 0.25, unit_weight)};
    JointMaterial joint = testing::springs("plane", 1e10, 1e10);
    JointStrength s;
    s.cohesion = Softening::constant(cohesion);
    s.friction = Softening::constant(std::tan(friction_deg * kDeg));
    joint.strength = s;
    c.joint_materials = {joint};
    const Vec2 foot = crack_foot();
    c.blocks = testing::blocks_of({Polygon{
        {{0, 0}, foot, {foot.x(), height}, {height / std::tan(face_deg * kDeg), height}}}});
    c.default_joint = "plane";
    SupportSpec base = testing::fixed({0, 0}, foot);
    base.joint_material = "plane";
    c.supports.push_back(base);
    StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "stages[0]"}};
    gravity.loads.gravity = Vec2(0.0, -1.0);
    if (water_depth > 0.0) {
      WaterSpec w;
      const double p = kWater * water_depth;
      w.lines.push_back({foot + Vec2(0, water_depth), foot, 0.0, p, {0, "crack"}});
      w.lines.push_back({foot, {0, 0}, p, 0.0, {0, "uplift"}});
      gravity.loads.water = w;
    }
    c.stages.push_back(gravity);
    return c;
  }
};

TEST(Water, PlaneFailureWithAWaterFilledTensionCrackFollowsHoekAndBray) {
  const PlaneFailure slope;
  for (const double depth : {0.0, 3.0, 6.0})  // dry, half-full, full
    expect_factor(factor_of_safety(slope.spec(depth)), slope.expected(depth), 1e-6);
}

}  // namespace
}  // namespace bimrock
