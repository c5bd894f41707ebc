// Verification: columns of stacked blocks of unequal heights, side by side on a dry base (dry
// joints: cohesionless, tensionless), stand under their own weight for every friction and
// dilation.
//
// Source of the expected outcome: the energy argument of running_bond_wall_test.cpp, independent
// of how the increments are solved. A Mohr-Coulomb joint dissipates (tan(phi) - tan(psi))
// |sigma_n| >= 0 per unit of slip and an open joint carries nothing, so a collapse needs a motion
// on which gravity does positive work; every block rests on the one below it, or on the flat
// rigid base, and none can move down without penetrating it. So every analysis carries the whole
// weight, and the supports' reaction balances it (a conservation law).
//
// The columns settle by different amounts (their heights differ, and so does the number of soft
// joints in each), so the vertical joints between them, at zero normal stress under no load, must
// slip from the first increment on. With dilation 0 the two slip flows of each such joint point
// are exactly opposite, and the first increment of these 19 blocks needs the
// perturbed LCP (IncrementLcp::perturbed) at 40 deg: the block rule's active sets are singular,
// the splitting's inner LCPs have no solution, and branch and bound runs out of budget.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"
#include "support/rectangle.hpp"
#include "support/support_reaction.hpp"

namespace bimrock {
namespace {

constexpr double kStackUnitWeight = 20e3;  // [N/m^3]
constexpr double kStackWidth = 0.725;      // of a column [m]

/// The heights of the blocks of each column, bottom up [m]: unequal, so that no horizontal
/// joint of one column meets one of its neighbour's.
const std::vector<std::vector<double>>& columns() {
  static const std::vector<std::vector<double>> heights{{1.057},
                                                        {0.825, 1.247, 1.479},
                                                        {1.021, 0.638, 0.754, 1.183},
                                                        {0.473, 1.260, 1.383, 0.359},
                                                        {0.390, 0.646, 0.733, 1.146},
                                                        {1.067, 0.988, 0.341}};
  return heights;
}

double weight() {
  double area = 0.0;
  for (const std::vector<double>& column : columns())
    for (double h : column)
      area += kStackWidth * h;
  return kStackUnitWeight * area;
}

CaseSpec column_stacks(double friction_deg, double dilation_deg) {
  CaseSpec c;
  c.file = "columns";
  c.block_materials = {testing::rock(20e9, 0.25, kStackUnitWeight)};
  c.joint_materials = {testing::dry_joint("dry", 1.05e9, 7.26e8, friction_deg, dilation_deg)};
  c.default_joint = "dry";
  std::vector<Polygon> blocks;
  for (std::size_t k = 0; k < columns().size(); ++k) {
    const double x = kStackWidth * static_cast<double>(k);
    double y = 0.0;
    for (double h : columns()[k]) {
      blocks.push_back(testing::rectangle(x, y, x + kStackWidth, y + h));
      y += h;
    }
  }
  c.blocks = testing::blocks_of(blocks);
  SupportSpec base =
      testing::fixed({0, 0}, {kStackWidth * static_cast<double>(columns().size()), 0});
  base.joint_material = "dry";
  c.supports.push_back(base);
  StageSpec gravity{"gravity", {}, 2, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0, -1);
  c.stages.push_back(gravity);
  return c;
}

TEST(ColumnStacks, StandUnderTheirWeightForEveryFrictionAndDilation) {
  for (const double phi : {20.0, 30.0, 38.7, 40.0, 50.0, 60.0, 70.0, 80.0}) {
    for (const double psi : {0.0, phi / 2.0, phi}) {
      const std::string what = "phi " + std::to_string(phi) + ", psi " + std::to_string(psi);
      const Model model = build_model(column_stacks(phi, psi));
      YieldPointIndex index;
      const std::vector<YieldPoint> points = make_yield_points(model, &index);
      double worst_balance = 0.0;
      const PlasticResult r = run_plastic_analysis(
          model, PlasticOptions{}, [&](const IncrementRecord& rec, const AnalysisState& state) {
            const PlasticParts plastic{&index, &state.points};
            const Vec2 load(0.0, -rec.stage_factor * weight());
            const Vec2 reaction = testing::support_reaction(model, state.u, plastic);
            worst_balance = std::max(worst_balance, (load + reaction).norm() / weight());
          });
      EXPECT_FALSE(r.stopped.has_value()) << what << ": " << r.stopped->reason;
      EXPECT_FALSE(r.collapse.has_value()) << what;
      EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12) << what;
      EXPECT_LE(worst_balance, 1e-8) << what;
    }
  }
}

}  // namespace
}  // namespace bimrock
