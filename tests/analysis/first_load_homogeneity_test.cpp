// A law that holds however the increments are solved: from an unstressed rest, a model whose
// joints have no cohesion and no tensile strength has yield functions positively homogeneous in
// the stress, so the first increment's LCP at a fraction t of the first load is the LCP of the
// whole load with q scaled by t. Its solutions scale with t: either every fraction carries or
// none does. The analysis may therefore carry the first load, or report the structure unstable
// under it, but never bracket a collapse at a finite fraction of it.
//
// The slope below (friction 21.9 deg, dilation 0, two joint sets, one of them non-persistent)
// was bracketed at [0, 0.5] of its weight when branch and bound took the simplex's verdict
// "empty" on its nodes as proof: round-off called feasible nodes of the 315-row degenerate LCP
// empty, and the search "proved" the step to 0.5 unsolvable while the step to 1 was left
// undecided. Every pruned node now needs a Farkas certificate of its own.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>

#include "support/support_reaction.hpp"

namespace bimrock {
namespace {

constexpr double kSlopeUnitWeight = 26.0e3;  // [N/m^3]

const std::string kCohesionlessSlope =
    "schema: 1\n"
    "analysis: {plane: strain, thickness: 1.0}\n"
    "materials:\n"
    "  rock: {E: 20.0e9, nu: 0.25, unit_weight: 26.0e3}\n"
    "joint_materials:\n"
    "  joint: {kn: 10.0e9, ks: 4.0e9, cohesion: 0.0, friction: 21.939, dilation: 0.000}\n"
    "domain:\n"
    "  outline: [[0, 0], [84.7478, 0], [84.7478, 36.4271], [48.3206, 36.4271],\n"
    "            [36.4271, 12.1424], [0, 12.1424]]\n"
    "  material: rock\n"
    "  joint_sets:\n"
    "    - {material: joint, dip: 96.508, spacing: 6.827, trace_length: 19.823, gap: 4.928,"
    " origin: [1.389, 1.834]}\n"
    "    - {material: joint, dip: 125.758, spacing: 7.197, origin: [7.017, 0.574]}\n"
    "supports:\n"
    "  - {line: [[0, 0], [84.7478, 0]], type: fixed}\n"
    "  - {line: [[0, 0], [0, 12.1424]], type: roller}\n"
    "  - {line: [[84.7478, 0], [84.7478, 36.4271]], type: roller}\n"
    "stages:\n"
    "  - {name: gravity, increments: 1, loads: {gravity: [0, -1]}}\n";

// The outline's area by the shoelace formula, times the unit weight: the weight per metre.
double homogeneity_slope_weight() {
  const double x[] = {0.0, 84.7478, 84.7478, 48.3206, 36.4271, 0.0};
  const double y[] = {0.0, 0.0, 36.4271, 36.4271, 12.1424, 12.1424};
  double twice_area = 0.0;
  for (int i = 0; i < 6; ++i)
    twice_area += x[i] * y[(i + 1) % 6] - x[(i + 1) % 6] * y[i];
  return 0.5 * twice_area * kSlopeUnitWeight;
}

TEST(FirstLoadHomogeneity, ACohesionlessSlopeCarriesItsWeightOrNoFractionOfIt) {
  const Model model = build_model(read_case_string(kCohesionlessSlope, "slope.yaml").spec);
  YieldPointIndex index;
  const std::vector<YieldPoint> points = make_yield_points(model, &index);
  const double weight = homogeneity_slope_weight();
  double worst_balance = 0.0;
  const PlasticResult r = run_plastic_analysis(
      model, PlasticOptions{}, [&](const IncrementRecord& rec, const AnalysisState& state) {
        const Vec2 reaction = testing::support_reaction(model, state.u, {&index, &state.points});
        const double down = rec.stage_factor * weight;
        worst_balance = std::max(worst_balance, (reaction - Vec2(0.0, down)).norm() / down);
      });
  ASSERT_FALSE(r.stopped.has_value()) << r.stopped->reason;
  if (r.collapse) {
    EXPECT_TRUE(r.collapse->unstable_at_first_load)
        << "collapse bracketed at [" << r.collapse->carried << ", " << r.collapse->failed
        << "] of the first load";
  } else {
    EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12);
    EXPECT_LE(worst_balance, 1e-8);
  }
}

}  // namespace
}  // namespace bimrock
