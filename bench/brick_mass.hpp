#pragma once
// The benchmark model: a square brick-pattern mass of about n blocks (rows staggered), example 1's
// rock and joints, on a fixed base, under gravity. Units SI.
#include <cmath>

#include <bimrock/geometry/brick_pattern.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock::bench {

inline CaseSpec brick_mass_case(int n_blocks) {
  const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(double(n_blocks)))));
  CaseSpec c;
  c.file = "bench";
  BlockMaterial rock;
  rock.name = "rock";
  rock.young = 89e9;
  rock.poisson = 0.26;
  rock.unit_weight = 26e3;
  c.block_materials = {rock};
  JointMaterial joint;
  joint.name = "joint";
  joint.normal_stiffness = 531.9e9;
  joint.shear_stiffness = 438.8e9;
  c.joint_materials = {joint};
  const double size = 0.2;
  for (const Polygon& p : brick_pattern(side, side, size, size, Stagger::rows))
    c.blocks.push_back({p, "rock", {}});
  c.default_joint = "joint";
  Selector base;
  base.kind = Selector::Kind::line;
  base.line = {Vec2(0, 0), Vec2(side * size, 0)};
  c.supports.push_back({base, SupportKind::fixed, std::nullopt, {0, "base"}});
  c.loads.gravity = Vec2(0, -1);
  return c;
}

}  // namespace bimrock::bench
