// Where yield is checked (yield_points.hpp). Independent numbers: conservation of length and
// area. The weights of the points of the joints that have a strength law add up to t times
// their total length (the points of subdivided joints, merged at the pieces' shared ends,
// included), those of the blocks to t times their areas (summed over triangle fans here); each
// interface point stands on its segment with its interface's normal.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/yield_points.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"
#include "support/random_convex.hpp"

namespace bimrock {
namespace {

constexpr double kPointsThickness = 0.8;

// Joints: strength, subdivided in three (end-point rule); the base: strength, Gauss; one side: a
// rigid support with no strength (no points). Blocks: every block has a strength.
Model blocks_with_strength(unsigned seed) {
  CaseSpec c;
  c.file = "points";
  c.settings.thickness = kPointsThickness;
  c.block_materials = {testing::rock(20e9, 0.25)};
  BlockStrength b;
  b.cohesion = 1e6;
  b.planes = 6;
  c.block_materials[0].strength = b;
  JointStrength strength;
  strength.cohesion = Softening::constant(1e5);
  JointMaterial joint = testing::springs("joint", 5e10, 2e10, Integration::lobatto);
  joint.subdivisions = 3;
  joint.strength = strength;
  JointMaterial base = testing::springs("base", 5e10, 2e10, Integration::gauss);
  base.strength = strength;
  c.joint_materials = {joint, base};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 6, seed));
  c.default_joint = "joint";
  SupportSpec fixed = testing::fixed({0, 0}, {2, 0});
  fixed.joint_material = "base";
  c.supports.push_back(fixed);
  c.supports.push_back(testing::roller({0, 0}, {0, 1.5}));
  return build_model(c);
}

TEST(YieldPoints, WeightsAddUpToTheLengthOfTheJointsAndTheAreaOfTheBlocks) {
  for (unsigned seed : {1u, 2u, 3u}) {
    const Model m = blocks_with_strength(seed);
    const std::vector<YieldPoint> points = make_yield_points(m);
    double joint_length = 0.0;
    double gauss_length = 0.0;
    int lobatto_pieces = 0;
    // Block pairs of the end-point joints: pieces of one joint share ends.
    std::map<std::pair<int, int>, int> pieces;
    for (const Interface& f : m.interfaces) {
      if (f.joint_material < 0 || !m.joint_materials[f.joint_material].strength)
        continue;
      (f.integration == Integration::gauss ? gauss_length : joint_length) += f.segment.length();
      if (f.integration == Integration::lobatto) {
        ++lobatto_pieces;
        ++pieces[{f.block_i, f.block_j}];
      }
    }
    double area = 0.0;
    for (const Block& b : m.blocks)
      area += testing::fan_moments(b.polygon).area;
    double interface_weight = 0.0;
    double gauss_weight = 0.0;
    double block_weight = 0.0;
    int lobatto_points = 0;
    for (const YieldPoint& p : points) {
      if (!p.is_interface()) {
        block_weight += p.weight;
        continue;
      }
      const Interface& f = m.interfaces[p.owner];
      EXPECT_EQ(p.normal, f.normal);
      EXPECT_LT(std::abs(cross(f.segment.direction(), p.position - f.segment.a)), 1e-12);
      (f.integration == Integration::gauss ? gauss_weight : interface_weight) += p.weight;
      lobatto_points += f.integration == Integration::lobatto ? 1 : 0;
    }
    EXPECT_NEAR(interface_weight, kPointsThickness * joint_length, 1e-12 * joint_length);
    EXPECT_NEAR(gauss_weight, kPointsThickness * gauss_length, 1e-12 * gauss_length);
    EXPECT_NEAR(block_weight, kPointsThickness * area, 1e-12 * area);
    // A joint of k pieces has k + 1 end points once the shared ends are merged.
    EXPECT_EQ(lobatto_points, lobatto_pieces + static_cast<int>(pieces.size()));
    EXPECT_EQ(lobatto_pieces, 3 * static_cast<int>(pieces.size()));
  }
}

}  // namespace
}  // namespace bimrock
