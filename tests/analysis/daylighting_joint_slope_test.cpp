// A rock slope (27 m high, face at 61 deg, no cohesion) cut by a vertical joint set and a
// non-persistent set dipping 29.518 deg out of the face, steeper than the joints' friction of
// 27.531 deg (dilation 19.4 deg). The blocks resting on the daylighting joints slide out as
// plane failures with free release on the vertical joints, whose factor of safety with no
// cohesion and no water is F = tan(phi) / tan(psi_p) whatever the block's size (limit
// equilibrium, Hoek & Bray, Rock Slope Engineering): 0.92064. So the slope cannot stand under
// its own weight, and the factor of safety of strength reduction must bracket that value.
//
// The first increment's LCP has 1 134 rows and is degenerate (every joint point at the apex of
// its yield surface): Lemke ends on rays that certify nothing, and the case stopped undecided
// at zero load until the exhaustive search, once the cuts of the first load fall below the
// bracket tolerance, solved branch and bound's root LP with a budget of its own on LCPs of up
// to 2 000 rows (an empty root gives the Farkas certificate).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>

namespace bimrock {
namespace {

const std::string kDaylightingSlope =
    "schema: 1\n"
    "analysis: {plane: strain, thickness: 1.0}\n"
    "materials:\n"
    "  rock: {E: 20.0e9, nu: 0.25, unit_weight: 26.0e3}\n"
    "joint_materials:\n"
    "  joint: {kn: 10.0e9, ks: 4.0e9, cohesion: 0.0, friction: 27.531, dilation: 19.433}\n"
    "domain:\n"
    "  outline: [[0, 0], [97.0292, 0], [97.0292, 40.9072], [56.1220, 40.9072],\n"
    "            [40.9072, 13.6357], [0, 13.6357]]\n"
    "  material: rock\n"
    "  joint_sets:\n"
    "    - {material: joint, dip: 89.128, spacing: 5.462, origin: [3.798, 0.908]}\n"
    "    - {material: joint, dip: 29.518, spacing: 4.808, trace_length: 21.939, gap: 2.889,"
    " origin: [2.895, 0.960]}\n"
    "supports:\n"
    "  - {line: [[0, 0], [97.0292, 0]], type: fixed}\n"
    "  - {line: [[0, 0], [0, 13.6357]], type: roller}\n"
    "  - {line: [[97.0292, 0], [97.0292, 40.9072]], type: roller}\n"
    "stages:\n"
    "  - {name: gravity, increments: 3, loads: {gravity: [0, -1]}}\n"
    "factor_of_safety: {materials: [joint], tolerance: 1.0e-3, largest: 3}\n";

TEST(DaylightingJointSlope, IsUnstableAndItsFactorOfSafetyIsThatOfPlaneSliding) {
  const Case c = read_case_string(kDaylightingSlope, "slope.yaml");
  const PlasticResult r = run_plastic_analysis(build_model(c.spec), c.plastic);
  ASSERT_FALSE(r.stopped.has_value()) << r.stopped->reason;
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_TRUE(r.collapse->unstable_at_first_load);
  ASSERT_TRUE(r.factor_of_safety.has_value());
  ASSERT_TRUE(r.factor_of_safety->collapse.has_value());
  const double deg = M_PI / 180.0;
  const double plane_sliding = std::tan(27.531 * deg) / std::tan(29.518 * deg);
  EXPECT_LE(r.factor_of_safety->lower, plane_sliding);
  EXPECT_GE(r.factor_of_safety->collapse->failed, plane_sliding);
}

}  // namespace
}  // namespace bimrock
