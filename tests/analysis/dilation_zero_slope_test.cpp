// A jointed slope whose joints have dilation below friction carries what the same slope carries
// with associated flow at the reduced friction phi* of Radenkovic and de Saxce,
// tan(phi*) = sin(phi) cos(psi) / (1 - sin(phi) sin(psi)): a load that the associated material
// of friction phi* carries, no flow rule of dilation psi <= phi can fail under (the
// reduced-friction lower bound of non-associated limit analysis).
//
// The slope: two joint sets, one non-persistent at friction 48 deg and dilation 0 (exactly
// opposite slip flows), one at 25 deg and 0.6 deg; gravity, then a surcharge behind the crest. Its
// first increment under gravity is solved only through the path of perturbed LCPs
// (IncrementLcp::perturbed) from associated flow down: branch and bound runs out of budget on its
// 459 rows.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>

namespace bimrock {
namespace {

constexpr double kDegree = M_PI / 180.0;

double reduced_friction_deg(double phi_deg, double psi_deg) {
  const double sp = std::sin(phi_deg * kDegree);
  return std::atan(sp * std::cos(psi_deg * kDegree) / (1.0 - sp * std::sin(psi_deg * kDegree))) /
         kDegree;
}

std::string joint(const std::string& name, double kn, double ks, double phi, double psi) {
  return "  " + name + ": {kn: " + std::to_string(kn) + ", ks: " + std::to_string(ks) +
         ", cohesion: 0, friction: " + std::to_string(phi) + ", dilation: " + std::to_string(psi) +
         ", tensile_strength: 0}\n";
}

// The slope with joint sets of friction and dilation (phi0, psi0) and (phi1, psi1) [deg].
PlasticResult run_slope(double phi0, double psi0, double phi1, double psi1) {
  const std::string text =
      "schema: 1\n"
      "analysis: {plane: strain, thickness: 1.0}\n"
      "materials:\n"
      "  rock: {E: 20.0e9, nu: 0.25, unit_weight: 20.0e3}\n"
      "joint_materials:\n" +
      joint("j0", 3.213e10, 6.738e9, phi0, psi0) + joint("j1", 1.854e9, 3.984e8, phi1, psi1) +
      "domain:\n"
      "  outline: [[-10, -10], [42.680842, -10], [42.680842, 29.581002], [18.303901, 29.581002],"
      " [0, 0], [-10, 0]]\n"
      "  material: rock\n"
      "  joint_sets:\n"
      "    - {material: j0, dip: 68.801, spacing: 5.614, trace_length: 6.780, gap: 0.706}\n"
      "    - {material: j1, dip: 94.216, spacing: 3.142}\n"
      "supports:\n"
      "  - {line: [[-10, -10], [42.680842, -10]], type: fixed}\n"
      "  - {line: [[-10, -10], [-10, 0]], type: roller}\n"
      "  - {line: [[42.680842, -10], [42.680842, 29.581002]], type: roller}\n"
      "stages:\n"
      "  - {name: gravity, increments: 2, loads: {gravity: [0, -1]}}\n"
      "  - {name: surcharge, increments: 8, loads: {tractions: [{line: [[18.303901, 29.581002],"
      " [42.680842, 29.581002]], normal: -7.23e+05}]}}\n";
  const Case c = read_case_string(text, "slope.yaml");
  return run_plastic_analysis(build_model(c.spec), c.plastic);
}

void expect_carried(const PlasticResult& r, const std::string& what) {
  EXPECT_FALSE(r.stopped.has_value()) << what << ": " << r.stopped->reason;
  EXPECT_FALSE(r.collapse.has_value()) << what;
  EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12) << what;
}

TEST(ReducedFrictionBound, ASlopeCarriesWhatAssociatedFlowAtReducedFrictionCarries) {
  const double phi0 = 48.07;
  const double psi0 = 0.0;
  const double phi1 = 25.012;
  const double psi1 = 0.618;
  const double reduced0 = reduced_friction_deg(phi0, psi0);
  const double reduced1 = reduced_friction_deg(phi1, psi1);
  ASSERT_NEAR(reduced0, 36.6, 0.1);
  ASSERT_NEAR(reduced1, 23.0, 0.1);
  // The bound's premise: associated flow at the reduced friction carries both stages.
  expect_carried(run_slope(reduced0, reduced0, reduced1, reduced1), "associated at phi*");
  // So must the joints' own flow rule.
  expect_carried(run_slope(phi0, psi0, phi1, psi1), "the model's flow rule");
}

}  // namespace
}  // namespace bimrock
