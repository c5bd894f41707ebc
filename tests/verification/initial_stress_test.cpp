// Verification: the initial stress, against closed forms.
//
// Sources of the expected numbers:
//  - a column of rock at rest under its own weight, held laterally (K0 conditions; e.g. Jaeger,
//    Cook & Zimmerman, Fundamentals of Rock Mechanics, 4th ed., 2007, section 5.6): sigma_v =
//    -gamma z, sigma_h = K0 sigma_v at depth z, with no displacement: the field is in
//    equilibrium (div sigma + b = 0) and meets the boundary conditions, so the first stage,
//    whose gravity it carries, must move nothing and yield nowhere;
//  - the principle of virtual work, block by block: a linear field in equilibrium with the
//    body forces balances the loads exactly in the block-interfaces model, so the residual of a
//    field whose unit weight differs from the rock's by d_gamma is the weight d_gamma t A of each
//    block, and a uniform field balances the boundary tractions equal to it;
//  - the Mohr-Coulomb criterion on a plane of the field (Jaeger et al. section 4.3): a joint
//    whose trace makes angle beta with the horizontal bears sigma_n and tau of the field on its
//    normal, and slips where |tau| > c - sigma_n tan(phi).
// Units: SI.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/model/initial_stress.hpp>

#include "support/cases.hpp"
#include "support/degrees.hpp"
#include "support/irregular_blocks.hpp"

namespace bimrock {
namespace {

constexpr double kColumnWidth = 4.0;
constexpr double kColumnHeight = 10.0;  // the ground level is the column's top
constexpr double kUnitWeight = 26e3;    // [N/m^3]
using testing::kDeg;

// An irregular column of jointed rock on a roller base between roller walls, the ground at its
// top; its joints frictional (phi, no cohesion or tension); one stage of gravity.
CaseSpec column(double k0, double friction_deg, unsigned seed = 7) {
  CaseSpec c;
  c.file = "k0_column";
  c.block_materials = {testing::rock(20e9, 0.25, kUnitWeight)};
  JointMaterial joint = testing::springs("joint", 1e11, 5e10);
  JointStrength s;
  s.friction = Softening::constant(std::tan(friction_deg * kDeg));
  joint.strength = s;
  c.joint_materials = {joint};
  c.default_joint = "joint";
  c.blocks = testing::blocks_of(testing::irregular_blocks(kColumnWidth, kColumnHeight, 9, seed));
  c.supports = {testing::roller({0, 0}, {kColumnWidth, 0}),
                testing::roller({0, 0}, {0, kColumnHeight}),
                testing::roller({kColumnWidth, 0}, {kColumnWidth, kColumnHeight})};
  StageSpec gravity{"in situ", {}, 1, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0.0, -1.0);
  c.stages = {gravity};
  InitialStressSpec field;
  field.gravity = InitialStressSpec::Gravity{kColumnHeight, kUnitWeight, k0};
  c.initial_stress = field;
  return c;
}

Eigen::Vector3d k0_stress(double k0, const Vec2& p) {
  const double vertical = -kUnitWeight * (kColumnHeight - p.y());
  return {k0 * vertical, vertical, 0.0};
}

TEST(InitialStress, AK0ColumnAtRestMovesNothingAndKeepsItsStress) {
  const double k0 = 0.5;
  const Model model = build_model(column(k0, 35.0));
  const PlasticResult r = run_plastic_analysis(model);
  ASSERT_FALSE(r.collapse || r.stopped);
  ASSERT_TRUE(r.initial_stress.has_value());
  EXPECT_LT(r.initial_stress->relative_residual, 1e-12);
  EXPECT_EQ(r.initial_stress->violated_points, 0);
  // Without the initial stress the same stage settles by gamma H^2 / E-ish: the scale of "no
  // displacement".
  Model bare = model;
  bare.initial_stress.reset();
  const double settled = run_plastic_analysis(bare).state.u.cwiseAbs().maxCoeff();
  ASSERT_GT(settled, 1e-7);
  EXPECT_LT(r.state.u.cwiseAbs().maxCoeff(), 1e-9 * settled);
  for (const IncrementRecord& rec : r.history)
    EXPECT_EQ(rec.yielding_points, 0);

  YieldPointIndex index;
  make_yield_points(model, &index);
  const PlasticParts plastic{&index, &r.state.points};
  const double scale = kUnitWeight * kColumnHeight;
  for (int b = 0; b < model.n_blocks(); ++b) {
    const BlockState s = block_state(model, b, r.state.u, plastic);
    const Eigen::Vector3d expected = k0_stress(k0, model.blocks[b].centroid);
    EXPECT_LT((s.stress - expected).cwiseAbs().maxCoeff(), 1e-9 * scale) << "block " << b;
  }
  for (int f = 0; f < model.n_interfaces(); ++f) {
    const Interface& face = model.interfaces[f];
    for (const InterfacePointState& p : interface_state(model, f, r.state.u, plastic)) {
      const Eigen::Vector3d sigma = k0_stress(k0, p.point);
      const Vec2 t(sigma(0) * face.normal.x() + sigma(2) * face.normal.y(),
                   sigma(2) * face.normal.x() + sigma(1) * face.normal.y());
      EXPECT_NEAR(p.stress(0), t.dot(face.normal), 1e-9 * scale) << "interface " << f;
      EXPECT_NEAR(p.stress(1), t.dot(Vec2(-face.normal.y(), face.normal.x())), 1e-9 * scale);
    }
  }
}

TEST(InitialStress, TheResidualOfAFieldLighterThanTheRockIsTheDifferenceOfWeight) {
  CaseSpec c = column(0.5, 35.0);
  const double lighter = 0.9 * kUnitWeight;
  c.initial_stress->gravity->unit_weight = lighter;
  const Model model = build_model(c);
  const PlasticResult r = run_plastic_analysis(model);
  ASSERT_TRUE(r.initial_stress.has_value());
  double largest = 0.0;  // the heaviest block's missing weight, t = 1
  for (const Block& b : model.blocks)
    largest = std::max(largest, (kUnitWeight - lighter) * b.area);
  EXPECT_NEAR(r.initial_stress->residual, largest, 1e-9 * largest);
}

TEST(InitialStress, AUniformFieldBalancesTractionsEqualToIt) {
  // [0, 3] x [0, 2] of irregular blocks on rollers along x = 0 and y = 0, pressed by -4 MPa on
  // x = 3 and -7 MPa on y = 2: the field (-4, -7, 0) MPa carries it all.
  CaseSpec c;
  c.file = "uniform";
  c.block_materials = {testing::rock(20e9, 0.25)};
  c.joint_materials = {testing::springs("joint", 1e11, 5e10)};
  c.default_joint = "joint";
  c.blocks = testing::blocks_of(testing::irregular_blocks(3.0, 2.0, 7, 3));
  StageSpec load{"in situ", {}, 1, std::nullopt, {0, "stages[0]"}};
  c.stages = {load};
  testing::load_biaxially(c, 3.0, 2.0, -4e6, -7e6);
  c.stages[0].loads.tractions = c.loads.tractions;
  c.loads.tractions.clear();
  InitialStressSpec field;
  field.uniform = Eigen::Vector3d(-4e6, -7e6, 0.0);
  c.initial_stress = field;
  const PlasticResult r = run_plastic_analysis(build_model(c));
  ASSERT_TRUE(r.initial_stress.has_value());
  EXPECT_LT(r.initial_stress->relative_residual, 1e-12);
  EXPECT_LT(r.state.u.cwiseAbs().maxCoeff(), 1e-15);
}

// The joints of the column whose Mohr-Coulomb function the K0 field violates (closed form on
// each joint's plane), counted by their yield points' positions.
int violated_by_field(const Model& model, double k0, double friction_deg) {
  int violated = 0;
  for (const YieldPoint& p : make_yield_points(model)) {
    const Eigen::Vector2d r = stress_on_plane(k0_stress(k0, p.position), p.normal);
    const double tol = 1e-9 * kUnitWeight * kColumnHeight;
    if (std::abs(r(1)) + r(0) * std::tan(friction_deg * kDeg) > tol)
      ++violated;
  }
  return violated;
}

TEST(InitialStress, PointsOutsideTheirStrengthAreRefusedOrYieldInTheFirstStage) {
  // K0 = 0.2 mobilizes asin(0.8 / 1.2) = 41.8 deg on the worst plane; the joints have 30 deg.
  const double k0 = 0.2, phi = 30.0;
  CaseSpec c = column(k0, phi);
  const Model refused = build_model(c);
  const int expected = violated_by_field(refused, k0, phi);
  ASSERT_GT(expected, 0) << "the column must have joints the field violates";
  EXPECT_THROW(run_plastic_analysis(refused), ModelError);

  c.initial_stress->allow_yield = true;
  const Model model = build_model(c);
  const PlasticResult r = run_plastic_analysis(model);
  ASSERT_TRUE(r.initial_stress.has_value());
  EXPECT_EQ(r.initial_stress->violated_points, expected);
  ASSERT_FALSE(r.stopped) << r.stopped->reason;
  ASSERT_FALSE(r.collapse) << r.collapse->carried << " " << r.collapse->failed;
  ASSERT_FALSE(r.history.empty());
  EXPECT_GT(r.history.front().yielding_points, 0);
  // Equilibrium after the redistribution: the base carries the column's weight (the roller
  // walls carry no shear), and no yield function is violated anywhere.
  YieldPointIndex index;
  make_yield_points(model, &index);
  const PlasticParts plastic{&index, &r.state.points};
  double base = 0.0;
  for (int f = 0; f < model.n_interfaces(); ++f) {
    const Interface& face = model.interfaces[f];
    if (!face.is_support() || face.normal.y() > -0.5)
      continue;
    for (const InterfacePointState& p : interface_state(model, f, r.state.u, plastic))
      base += 0.5 * face.segment.length() * p.stress(0);  // the end points' rule (lobatto)
  }
  const double weight = kUnitWeight * kColumnWidth * kColumnHeight;
  EXPECT_NEAR(base, -weight, 1e-9 * weight);
  const YieldEvaluator yield(model, r.points);
  YieldValues f;
  double scale = 0.0;
  yield.evaluate(r.state.points, r.state.u, f, &scale);
  EXPECT_LE(f.f.maxCoeff(), 1e-6 * scale);
}

}  // namespace
}  // namespace bimrock
