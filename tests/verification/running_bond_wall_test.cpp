// Verification: walls of dry masonry in running bond (cohesionless, tensionless joints) standing
// on a dry base under their own weight, for every friction and dilation.
//
// Source of the expected outcome (an energy argument, independent of how the increments are
// solved): a collapse is a motion of the blocks under constant loads in which the loads' work
// equals the work the joints dissipate. A Mohr-Coulomb joint at yield dissipates
// (tan(phi) - tan(psi)) |sigma_n| per unit of slip, never a negative work for psi <= phi, and an
// open joint carries no stress. Each block of a wall on a flat rigid base rests on the course
// below it, so no block can move down without penetrating it: gravity does no positive work on
// any admissible motion, and no collapse can occur. So every analysis carries the whole weight,
// and the supports' reaction balances it (a conservation law).
//
// Among them, with dilation 0: the first increments of 4 x 8 bricks at 56 and 60 deg need the
// complete method's polish to take an open point's slip row active at a cohesionless apex, and
// that of 3 x 4 bricks at 50 deg the splitting on the dense route, where branch and bound runs
// out of budget.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/geometry/brick_pattern.hpp>

#include "support/cases.hpp"
#include "support/support_reaction.hpp"

namespace bimrock {
namespace {

constexpr double kMasonryUnitWeight = 20e3;  // [N/m^3]

struct Wall {
  int bricks = 0;   // per course (a shifted course holds one more: half bricks at its ends)
  int courses = 0;  // courses
  double width = 0.0;
  double height = 0.0;  // of a brick [m]
};

CaseSpec running_bond_wall(const Wall& wall, double friction_deg, double dilation_deg) {
  CaseSpec c;
  c.file = "wall";
  c.block_materials = {testing::rock(20e9, 0.25, kMasonryUnitWeight)};
  c.joint_materials = {testing::dry_joint("dry", 1e11, 2.5e10, friction_deg, dilation_deg)};
  c.default_joint = "dry";
  c.blocks = testing::blocks_of(
      brick_pattern(wall.bricks, wall.courses, wall.width, wall.height, Stagger::rows));
  SupportSpec base = testing::fixed({0, 0}, {wall.bricks * wall.width, 0});
  base.joint_material = "dry";
  c.supports.push_back(base);
  StageSpec gravity{"gravity", {}, 2, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0, -1);
  c.stages.push_back(gravity);
  return c;
}

TEST(RunningBondWall, StandsUnderItsWeightForEveryFrictionAndDilation) {
  const std::vector<Wall> walls{
      {2, 5, 0.4, 0.1}, {3, 4, 0.4, 0.1}, {4, 8, 0.3, 0.15}, {2, 6, 0.5, 0.2}};
  for (const Wall& wall : walls) {
    const double weight =
        kMasonryUnitWeight * wall.bricks * wall.width * wall.courses * wall.height;
    for (const double phi : {20.0, 30.0, 40.0, 50.0, 56.0, 60.0, 70.0, 80.0}) {
      for (const double psi : {0.0, phi / 2.0, phi}) {
        const std::string what = std::to_string(wall.bricks) + " x " +
                                 std::to_string(wall.courses) + ", phi " + std::to_string(phi) +
                                 ", psi " + std::to_string(psi);
        const Model model = build_model(running_bond_wall(wall, phi, psi));
        YieldPointIndex index;
        const std::vector<YieldPoint> points = make_yield_points(model, &index);
        double worst_balance = 0.0;
        const PlasticResult r = run_plastic_analysis(
            model, PlasticOptions{}, [&](const IncrementRecord& rec, const AnalysisState& state) {
              const PlasticParts plastic{&index, &state.points};
              const Vec2 load(0.0, -rec.stage_factor * weight);
              const Vec2 reaction = testing::support_reaction(model, state.u, plastic);
              worst_balance = std::max(worst_balance, (load + reaction).norm() / weight);
            });
        EXPECT_FALSE(r.stopped.has_value()) << what << ": " << r.stopped->reason;
        EXPECT_FALSE(r.collapse.has_value()) << what;
        EXPECT_NEAR(r.state.stage_factor, 1.0, 1e-12) << what;
        EXPECT_LE(worst_balance, 1e-8) << what;
      }
    }
  }
}

}  // namespace
}  // namespace bimrock
