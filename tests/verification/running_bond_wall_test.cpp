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
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/geometry/brick_pattern.hpp>

#include "support/cases.hpp"
#include "support/stands_under_weight.hpp"

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
  c.supports.push_back(testing::base_of({0, 0}, {wall.bricks * wall.width, 0}, "dry"));
  c.stages.push_back(testing::gravity_stage(2));
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
        testing::expect_stands_under_weight(build_model(running_bond_wall(wall, phi, psi)), weight,
                                            what);
      }
    }
  }
}

}  // namespace
}  // namespace bimrock
