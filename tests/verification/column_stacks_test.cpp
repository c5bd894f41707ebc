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
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/cases.hpp"
#include "support/rectangle.hpp"
#include "support/stands_under_weight.hpp"

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
  const double width = kStackWidth * static_cast<double>(columns().size());
  c.supports.push_back(testing::base_of({0, 0}, {width, 0}, "dry"));
  c.stages.push_back(testing::gravity_stage(2));
  return c;
}

TEST(ColumnStacks, StandUnderTheirWeightForEveryFrictionAndDilation) {
  for (const double phi : {20.0, 30.0, 38.7, 40.0, 50.0, 60.0, 70.0, 80.0}) {
    for (const double psi : {0.0, phi / 2.0, phi}) {
      const std::string what = "phi " + std::to_string(phi) + ", psi " + std::to_string(psi);
      testing::expect_stands_under_weight(build_model(column_stacks(phi, psi)), weight(), what);
    }
  }
}

TEST(ColumnStacks, NoRouteOfTheSolverReportsThemUnstable) {
  // The same stacks at 50 deg without dilation, each increment solved with a route of the
  // solver left out. Where load control leaves the first increment undecided, displacement
  // control finds the load factor level at zero (the cohesionless joints have no strength
  // there): that is no proof, and the stacks stand, so the analysis may stop but never report
  // a collapse.
  for (const int variant : {0, 1}) {
    PlasticTuning tuning;
    if (variant == 0)
      tuning.solver.splitting = false;
    else
      tuning.solver.active_set = false;
    const PlasticResult r =
        run_plastic_analysis(build_model(column_stacks(50.0, 0.0)), PlasticOptions{}, {}, tuning);
    EXPECT_FALSE(r.collapse.has_value()) << "variant " << variant;
    if (r.stopped) {
      EXPECT_NE(r.stopped->reason.find("proves no collapse"), std::string::npos)
          << r.stopped->reason;
      // The analysis ran associated flow itself: the reason says what that found (it carries
      // the stacks), not advice to try it.
      EXPECT_NE(r.stopped->reason.find("associated flow carries this stage"), std::string::npos)
          << r.stopped->reason;
      EXPECT_EQ(r.stopped->reason.find("from above"), std::string::npos) << r.stopped->reason;
    }
  }
}

}  // namespace
}  // namespace bimrock
