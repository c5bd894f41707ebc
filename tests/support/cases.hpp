#pragma once
// Small case builders shared by tests: they write CaseSpecs the way a case file would.
#include <cmath>
#include <string>
#include <vector>

#include <bimrock/geometry/brick_pattern.hpp>
#include <bimrock/model/case_spec.hpp>

#include "support/degrees.hpp"

namespace bimrock::testing {

inline Selector on_line(Vec2 a, Vec2 b) {
  Selector s;
  s.kind = Selector::Kind::line;
  s.line = {a, b};
  s.source.item = "line";
  return s;
}

inline Selector with_orientation(double angle_deg) {
  Selector s;
  s.kind = Selector::Kind::orientation;
  s.angle_deg = angle_deg;
  s.source.item = "orientation";
  return s;
}

inline BlockMaterial rock(double young, double poisson, double unit_weight = 0.0) {
  BlockMaterial m;
  m.name = "rock";
  m.young = young;
  m.poisson = poisson;
  m.unit_weight = unit_weight;
  m.source = {0, "materials.rock"};
  return m;
}

inline JointMaterial springs(const std::string& name, double kn, double ks,
                             Integration rule = Integration::lobatto) {
  JointMaterial j;
  j.name = name;
  j.normal_stiffness = kn;
  j.shear_stiffness = ks;
  j.integration = rule;
  j.source.item = name;
  return j;
}

/// Springs with a dry joint's strength: Mohr-Coulomb friction and dilation (in degrees), no
/// cohesion and no tension, as dry masonry and clean rock joints have.
inline JointMaterial dry_joint(const std::string& name, double kn, double ks, double friction_deg,
                               double dilation_deg) {
  JointMaterial j = springs(name, kn, ks);
  JointStrength s;
  s.friction = Softening::constant(std::tan(friction_deg * kDeg));
  s.dilation = std::tan(dilation_deg * kDeg);
  j.strength = s;
  return j;
}

inline JointMaterial continuum(double penalty_factor) {
  JointMaterial j;
  j.name = "continuum";
  j.kind = JointMaterial::Kind::continuum;
  j.penalty_factor = penalty_factor;
  j.integration = Integration::gauss;
  j.source.item = "continuum";
  return j;
}

inline std::vector<BlockSpec> blocks_of(const std::vector<Polygon>& polygons,
                                        const std::string& material = "rock") {
  std::vector<BlockSpec> blocks;
  for (std::size_t k = 0; k < polygons.size(); ++k)
    blocks.push_back(
        {polygons[k], material, {static_cast<int>(k) + 1, "blocks[" + std::to_string(k) + "]"}});
  return blocks;
}

inline SupportSpec roller(Vec2 a, Vec2 b) {
  return {on_line(a, b), SupportKind::roller, std::nullopt, {0, "supports"}};
}

inline SupportSpec fixed(Vec2 a, Vec2 b) {
  return {on_line(a, b), SupportKind::fixed, std::nullopt, {0, "supports"}};
}

/// A fixed support along a line whose springs are the joint material `joint` (a dry base).
inline SupportSpec base_of(Vec2 a, Vec2 b, const std::string& joint) {
  SupportSpec base = fixed(a, b);
  base.joint_material = joint;
  return base;
}

/// A stage of the structure's own weight (gravity downwards) in `increments` steps.
inline StageSpec gravity_stage(int increments) {
  StageSpec gravity{"gravity", {}, increments, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0, -1);
  return gravity;
}

/// Uniform normal traction (tension positive) on the edges along a line.
inline TractionSpec pressure_on(Vec2 a, Vec2 b, double normal) {
  return {on_line(a, b), normal, 0.0, {0, "tractions"}};
}

/// A w x h rectangle resting on a roller along y = 0 and a roller along x = 0, loaded by normal
/// tractions s_x on x = w and s_y on y = h: the classic quarter-model boundary conditions under
/// which a homogeneous body takes the uniform stress (s_x, s_y, 0).
inline void load_biaxially(CaseSpec& c, double w, double h, double s_x, double s_y) {
  c.supports.push_back(roller({0, 0}, {w, 0}));
  c.supports.push_back(roller({0, 0}, {0, h}));
  if (s_x != 0.0)
    c.loads.tractions.push_back(pressure_on({w, 0}, {w, h}, s_x));
  if (s_y != 0.0)
    c.loads.tractions.push_back(pressure_on({0, h}, {w, h}, s_y));
}

}  // namespace bimrock::testing
