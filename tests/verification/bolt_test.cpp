// Rock bolts against closed forms. Two unit squares stacked on a fixed base, the joint between
// them and a bolt through it (docs/formulation.md, "Bolts"). The blocks are 10^6 times stiffer
// than the joint (E t / h = 1e14 N/m against k_n t L = 1e8 N/m), so the joint and the bolt are the
// only compliances: the closed forms neglect the blocks' share, 1e-6 of the joint's, and the
// tolerances are 1e-5 relative where they do (1e-9 where equilibrium alone decides).
// - Pretension: the upper block's equilibrium makes the joint's compression equal to the
//   bolts' pretension (w T0, w bolts in the model's thickness).
// - A pull P on the upper block: the joint (k_j) and the bolts (w k_b) share it while the joint is
//   closed, so the joint's compression falls as w T0 - P k_j / (k_j + w k_b) and the joint opens at
//   P = w T0 (1 + w k_b / k_j), the separation load of a preloaded bolted joint; opened, the
//   bolts carry P alone and yield at P = w N_y, where the block lifts off (a collapse).
// - A grouted bolt across a joint that slides (Tresca, c): the block slides at H = c L t + w V_y,
//   and the factor of safety divides c only.
// Units: SI.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr double kJointStiffness = 1e8;  // k_n = k_s [Pa/m]; k_j = k_n t L [N/m]
constexpr double kBoltStiffness = 1e7;   // k_b [N/m], per bolt
constexpr double kPretension = 1e5;      // T0 [N], per bolt
constexpr double kCapacity = 3e5;        // N_y [N], per bolt
constexpr double kSpacing = 0.5;         // [m]: w = t / spacing = 2 bolts in the model
constexpr double kBolts = 2.0;           // w
constexpr double kJointCohesion = 1e4;   // [Pa]

// The two squares [0, 1] x [0, 1] and [0, 1] x [1, 2] on a fixed base, the joint between them
// with a tension cut-off at 0 and cohesion (friction 0: a Tresca joint, associated); stages
// `stages`. No gravity.
Model stacked(const std::vector<StageSpec>& stages, double tensile = 0.0) {
  CaseSpec c;
  c.file = "stacked";
  c.block_materials = {testing::rock(1e14, 0.0)};
  JointMaterial joint = testing::springs("joint", kJointStiffness, kJointStiffness);
  JointStrength s;
  s.cohesion = Softening::constant(kJointCohesion);
  s.tensile = Softening::constant(tensile);
  joint.strength = s;
  c.joint_materials = {joint};
  c.default_joint = "joint";
  c.blocks = testing::blocks_of(
      {Polygon{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, Polygon{{{0, 1}, {1, 1}, {1, 2}, {0, 2}}}});
  c.supports = {testing::fixed({0, 0}, {1, 0})};
  c.stages = stages;
  return build_model(c);
}

int upper_block(const Model& m) {
  return m.blocks[0].centroid.y() > 1.0 ? 0 : 1;
}

// A vertical anchored bolt from `head` down to `anchor` (blocks `a` and `b`), installed at stage 0.
void anchor_between(Model& m, int a, Vec2 head, int b, Vec2 anchor, double pretension) {
  Bolt bolt;
  bolt.name = "anchor";
  bolt.from = head;
  bolt.to = anchor;
  bolt.axial_stiffness = kBoltStiffness;
  bolt.capacity = kCapacity;
  bolt.pretension = pretension;
  bolt.per_model = 1.0 / kSpacing;
  m.bolts = {bolt};
  m.bolt_springs = {BoltSpring{0, a, b, head, anchor, Vec2(0.0, -1.0)}};
}

// An anchored bolt from the top of the upper block to the lower block's centre.
void bolt_through(Model& m, double pretension) {
  const int up = upper_block(m);
  anchor_between(m, up, Vec2(0.5, 2.0), 1 - up, Vec2(0.5, 0.5), pretension);
}

StageSpec stage(const std::string& name, int increments, Vec2 force = Vec2::Zero()) {
  StageSpec st{name, {}, increments, std::nullopt, {0, "stages[]"}};
  if (force.squaredNorm() > 0.0)
    st.loads.points = {PointLoadSpec{Vec2(0.5, 1.5), force, {0, "stages[].loads.points[0]"}}};
  return st;
}

// The joint's normal force [N] (tension positive): t integral sigma_n ds.
double joint_normal_force(const Model& m, const PlasticResult& r, const YieldPointIndex& index) {
  for (int k = 0; k < m.n_interfaces(); ++k) {
    const Interface& f = m.interfaces[k];
    if (f.is_support())
      continue;
    const InterfaceState s = interface_state(m, k, r.state.u, {&index, &r.state.points});
    return m.settings.thickness * 0.5 * f.segment.length() * (s[0].stress(0) + s[1].stress(0));
  }
  return NAN;
}

Eigen::Vector2d bolt_force(const Model& m, const PlasticResult& r) {
  for (std::size_t p = 0; p < r.points.size(); ++p)
    if (r.points[p].is_bolt())
      return local_stress(m, r.points[p], r.state.points[p], r.state.u);
  return {NAN, NAN};
}

TEST(Bolt, PretensionCompressesTheJointByItsForce) {
  Model m = stacked({stage("install", 1)});
  bolt_through(m, kPretension);
  YieldPointIndex index;
  static_cast<void>(make_yield_points(m, &index));
  const PlasticResult r = run_plastic_analysis(m, {});
  ASSERT_FALSE(r.collapse);
  ASSERT_FALSE(r.stopped);
  EXPECT_NEAR(bolt_force(m, r)(0), kPretension, 1e-9 * kPretension);
  EXPECT_NEAR(joint_normal_force(m, r, index), -kBolts * kPretension, 1e-9 * kPretension);
  // The upper block moved down by the compression over the joint's stiffness (rigid blocks).
  const Vec2 head = displacement_at(m, upper_block(m), Vec2(0.5, 2.0), r.state.u);
  EXPECT_NEAR(head.y(), -kBolts * kPretension / kJointStiffness, 1e-5 * kPretension / 1e8);
}

// The pretensioned pair pulled up by `pull` [N] at the upper block's centroid, and its analysis.
struct Pulled {
  Model model;
  PlasticResult result;
};

Pulled pulled(double pull, int increments = 1) {
  Pulled p{stacked({stage("install", 1), stage("pull", increments, Vec2(0.0, pull))}), {}};
  bolt_through(p.model, kPretension);
  p.result = run_plastic_analysis(p.model, {});
  return p;
}

bool joint_open(const PlasticResult& r) {
  for (std::size_t p = 0; p < r.points.size(); ++p)
    if (r.points[p].is_interface() && r.state.points[p].gap > 0.0)
      return true;
  return false;
}

TEST(Bolt, APullOpensThePretensionedJointAtTheSeparationLoad) {
  const double k_j = kJointStiffness * 1.0 * 1.0;
  const double separation = kBolts * kPretension * (1.0 + kBolts * kBoltStiffness / k_j);
  const Pulled below = pulled(0.999 * separation);
  ASSERT_FALSE(below.result.collapse);
  EXPECT_FALSE(joint_open(below.result));
  // Closed, the joint and the bolts share the pull by their stiffnesses.
  const double lift = 0.999 * separation / (k_j + kBolts * kBoltStiffness);
  EXPECT_NEAR(bolt_force(below.model, below.result)(0), kPretension + kBoltStiffness * lift,
              1e-5 * kPretension);
  const Pulled above = pulled(1.001 * separation);
  ASSERT_FALSE(above.result.collapse);
  EXPECT_TRUE(joint_open(above.result));
  // Open, the bolts carry the pull alone.
  EXPECT_NEAR(bolt_force(above.model, above.result)(0), 1.001 * separation / kBolts,
              1e-9 * kPretension);
}

TEST(Bolt, ThePulledBlockLiftsOffWhenTheBoltsYield) {
  const double pull = 2.0 * kBolts * kCapacity;
  const PlasticResult r = pulled(pull, 8).result;
  ASSERT_TRUE(r.collapse);
  EXPECT_EQ(r.collapse->stage, 1);
  const double lift_off = kBolts * kCapacity / pull;  // stage factor 0.5
  EXPECT_LE(r.collapse->carried, lift_off * (1.0 + 1e-9));
  EXPECT_GE(r.collapse->failed, lift_off * (1.0 - 1e-9));
  EXPECT_LT(r.collapse->failed - r.collapse->carried, 2e-4 * lift_off);
}

// The dowel: a grouted bolt through the joint, with a shear capacity.
void dowel_through(Model& m, double shear_capacity) {
  Bolt b;
  b.name = "dowel";
  b.kind = BoltSpec::Kind::grouted;
  b.from = Vec2(0.5, 2.0);
  b.to = Vec2(0.5, 0.5);
  b.axial_stiffness = 1e8;
  b.shear_stiffness = 1e7;
  b.capacity = 1e6;
  b.shear_capacity = shear_capacity;
  b.per_model = kBolts;
  m.bolts = {b};
  const int up = upper_block(m);
  m.bolt_springs = {BoltSpring{0, up, 1 - up, Vec2(0.5, 1.0), Vec2(0.5, 1.0), Vec2(0.0, -1.0)}};
}

constexpr double kDowelShearCapacity = 5e3;  // V_y [N], per bolt

TEST(Bolt, AGroutedBoltAddsItsShearCapacityToTheJoints) {
  const double sliding = kJointCohesion * 1.0 * 1.0 + kBolts * kDowelShearCapacity;
  const double push = 2.0 * sliding;
  // No tension cut-off in the way: the push's moment must not open the joint.
  Model m = stacked({stage("push", 10, Vec2(push, 0.0))}, 1e9);
  dowel_through(m, kDowelShearCapacity);
  const PlasticResult r = run_plastic_analysis(m, {});
  ASSERT_TRUE(r.collapse);
  const double at = sliding / push;
  EXPECT_LE(r.collapse->carried, at * (1.0 + 1e-9));
  EXPECT_GE(r.collapse->failed, at * (1.0 - 1e-9));
  EXPECT_LT(r.collapse->failed - r.collapse->carried, 2e-4 * at);
}

// Strength reduction divides the joint's cohesion, not the bolts' capacity: under a push H the
// block slides when c L t / F + w V_y = H, F = c L t / (H - w V_y).
TEST(Bolt, TheFactorOfSafetyKeepsTheBoltsCapacity) {
  const double push = 1.2e4;
  Model m = stacked({stage("push", 1, Vec2(push, 0.0))}, 1e9);
  dowel_through(m, kDowelShearCapacity);
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  const PlasticResult r = run_plastic_analysis(m, options);
  ASSERT_FALSE(r.collapse);
  ASSERT_TRUE(r.factor_of_safety && r.factor_of_safety->collapse);
  const double f = kJointCohesion * 1.0 * 1.0 / (push - kBolts * kDowelShearCapacity);  // 5
  EXPECT_LE(r.factor_of_safety->lower, f * (1.0 + 1e-6));
  EXPECT_GE(r.factor_of_safety->collapse->failed, f * (1.0 - 1e-6));
  EXPECT_LT(r.factor_of_safety->collapse->failed - r.factor_of_safety->lower, 1.1e-3 * f);
}

// Excavating a bolt's head block takes the bolt with it: the middle of three stacked squares,
// squeezed between the anchor it holds and the joint above it, is freed of both at once (their
// forces on it are opposite), so it ends where it started, unstrained. No gravity.
TEST(Bolt, ExcavatingTheHeadsBlockReleasesTheBoltWithIt) {
  CaseSpec c;
  c.file = "three";
  c.block_materials = {testing::rock(1e14, 0.0)};
  c.joint_materials = {testing::springs("joint", kJointStiffness, kJointStiffness)};
  c.default_joint = "joint";
  c.blocks = testing::blocks_of({Polygon{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}},
                                 Polygon{{{0, 1}, {1, 1}, {1, 2}, {0, 2}}},
                                 Polygon{{{0, 2}, {1, 2}, {1, 3}, {0, 3}}}});
  c.supports = {testing::fixed({0, 0}, {1, 0})};
  StageSpec excavate = stage("excavate the top", 1);
  excavate.excavate =
      BlockSelector{BlockSelector::Kind::box, {}, BBox{{0.1, 2.1}, {0.9, 2.9}}, {}, {},
                    {0, "stages[1].excavate"}};
  c.stages = {stage("install", 1), excavate};
  Model m = build_model(c);
  const auto block_at = [&](double y) {
    for (int b = 0; b < m.n_blocks(); ++b)
      if (std::abs(m.blocks[b].centroid.y() - y) < 1e-9)
        return b;
    return -1;
  };
  const int top = block_at(2.5);
  const int middle = block_at(1.5);
  anchor_between(m, top, Vec2(0.5, 3.0), middle, Vec2(0.5, 1.5), kPretension);
  const PlasticResult r = run_plastic_analysis(m, {});
  ASSERT_FALSE(r.collapse || r.stopped);
  // Jacked, the top block moved down by the pretension over the joint's stiffness; excavated,
  // the middle one is back where it was.
  const double squeeze = kBolts * kPretension / kJointStiffness;
  EXPECT_NEAR(r.state.u(6 * top + 1), -squeeze, 1e-5 * squeeze);
  EXPECT_LT(r.state.u.segment<6>(6 * middle).cwiseAbs().maxCoeff(), 1e-9 * squeeze);
}

}  // namespace
}  // namespace bimrock
