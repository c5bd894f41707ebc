#pragma once
// A block on an inclined plane: the slope is the x-axis and gravity is tilted by the slope
// angle, which is the same problem turned (exact); downslope is +x. Joints: Mohr-Coulomb
// without cohesion, no tension, dilation `dilation_deg` (0: none). The base block [-2, w + 2] x
// [-1, 0] is fixed; the block [0, w] x [0, h] rests on it. Stage 1 applies gravity, stage 2 (if
// `push` is non-zero) the force `push` at the block's centroid in `increments` steps. Units: SI.
#include <cmath>
#include <optional>

#include <bimrock/model/case_spec.hpp>

#include "support/cases.hpp"
#include "support/degrees.hpp"

namespace bimrock::testing {

struct Incline {
  double width = 2.0;
  double height = 0.5;
  double slope_deg = 20.0;
  double friction_deg = 30.0;
  double dilation_deg = 0.0;
  double unit_weight = 20e3;
  double k = 1e9;  // k_n = k_s [Pa/m]

  [[nodiscard]] double weight() const { return unit_weight * width * height; }
};

inline CaseSpec incline_case(const Incline& in, Vec2 push = Vec2::Zero(), int increments = 10) {
  CaseSpec c;
  c.file = "incline";
  c.block_materials = {rock(10e9, 0.2, in.unit_weight)};
  JointMaterial joint = springs("joint", in.k, in.k);
  JointStrength s;
  s.friction = Softening::constant(std::tan(in.friction_deg * kDeg));
  s.dilation = std::tan(in.dilation_deg * kDeg);
  joint.strength = s;
  c.joint_materials = {joint};
  c.blocks = blocks_of({Polygon{{{-2, -1}, {in.width + 2, -1}, {in.width + 2, 0}, {-2, 0}}},
                        Polygon{{{0, 0}, {in.width, 0}, {in.width, in.height}, {0, in.height}}}});
  c.default_joint = "joint";
  c.supports.push_back(fixed({-2, -1}, {in.width + 2, -1}));
  const double t = in.slope_deg * kDeg;
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(std::sin(t), -std::cos(t));  // downslope is +x
  c.stages.push_back(gravity);
  if (push.squaredNorm() > 0.0) {
    StageSpec load{"push", {}, increments, std::nullopt, {0, "stages[1]"}};
    load.loads.points.push_back({Vec2(0.5 * in.width, 0.5 * in.height), push, {0, "push"}});
    c.stages.push_back(load);
  }
  return c;
}

}  // namespace bimrock::testing
