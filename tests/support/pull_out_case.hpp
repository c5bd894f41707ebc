#pragma once
// The paper's example 2 (Zhang & Lu): a wall of 3 x 4 half-bricks (2 m x 0.5 m, staggered rows)
// on an elastic fixed base, joints of the given strength, gravity, then a horizontal point load
// `total` [N] at A = (6, 0.75) in `increments` steps. Units: SI.
#include <bimrock/geometry/brick_pattern.hpp>
#include <bimrock/model/case_spec.hpp>

#include "support/cases.hpp"

namespace bimrock::testing {

inline CaseSpec pull_out_case(const JointStrength& strength, double total, int increments) {
  CaseSpec c;
  c.file = "pull_out";
  c.block_materials = {rock(89e9, 0.26, 16e3)};
  JointMaterial vertical = springs("vertical", 395.9e9, 438.8e9);
  JointMaterial horizontal = springs("horizontal", 531.9e9, 438.8e9);
  vertical.strength = horizontal.strength = strength;
  JointMaterial base = springs("base", 531.9e9, 438.8e9);  // elastic
  c.joint_materials = {vertical, horizontal, base};
  c.blocks = blocks_of(brick_pattern(3, 4, 2.0, 0.5, Stagger::rows));
  c.default_joint = "vertical";
  c.joint_rules.push_back({with_orientation(0.0), "horizontal", {0, "rule"}});
  SupportSpec support = fixed({0, 0}, {6, 0});
  support.joint_material = "base";
  c.supports.push_back(support);
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "gravity"}};
  gravity.loads.gravity = Vec2(0, -1);
  StageSpec pull{"pull", {}, increments, std::nullopt, {0, "pull"}};
  pull.loads.points.push_back({Vec2(6.0, 0.75), Vec2(total, 0.0), {0, "P"}});
  c.stages = {gravity, pull};
  c.monitors.push_back({"A", Vec2(6.0, 0.75), {0, "A"}});
  return c;
}

}  // namespace bimrock::testing
