// The yield functions of every point at once (yield_values.hpp). Sources: a second method, the
// linearization of each point's modes (yield_modes.hpp: local_operator's B matrices, the
// laws with their gradients); and f's linearity in the stress at a fixed plastic state, which
// the choice of candidates relies on (f(U + dU) - f(U) = a D E dU, with a from linearize).
#include <gtest/gtest.h>

#include <cmath>

#include <Eigen/Dense>

#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/assembly/yield_values.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"

namespace bimrock {
namespace {

// Irregular blocks on a fixed base: joints (softening), supports, and blocks that yield.
Model jointed_blocks() {
  CaseSpec c;
  c.file = "values";
  c.block_materials = {testing::rock(20e9, 0.25, 2e4)};
  BlockStrength b;
  b.cohesion = 1e6;
  b.friction = std::sin(0.5);
  b.dilation = std::sin(0.2);
  b.planes = 12;
  c.block_materials[0].strength = b;
  JointMaterial j = testing::springs("joint", 5e10, 2e10);
  JointStrength s;
  s.cohesion = {1e5, 2e4, 1e-3};
  s.friction = {0.7, 0.5, 2e-3};
  s.dilation = 0.1;
  s.tensile = {5e4, 0.0, 1e-4};
  j.strength = s;
  c.joint_materials = {j};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 5, 3));
  c.default_joint = "joint";
  SupportSpec base = testing::fixed({0, 0}, {2, 0});
  base.joint_material = "joint";  // a base that can slide and lift off: support points
  c.supports.push_back(base);
  return build_model(c);
}

// Plastic states with slip, openings and plastic strains, some past their softening's end.
std::vector<PlasticState> some_states(std::size_t n) {
  std::vector<PlasticState> states(n);
  for (std::size_t p = 0; p < n; ++p) {
    const double t = static_cast<double>(p);
    states[p].plastic = 1e-5 * Eigen::Vector3d(std::sin(t), std::cos(1.3 * t), std::sin(0.7 * t));
    states[p].slip = 1e-3 * (1.0 + std::sin(2.1 * t));
    states[p].gap = p % 3 == 0 ? 5e-5 : 0.0;
    states[p].max_gap = p % 3 == 0 ? 2e-4 : 0.0;
  }
  return states;
}

TEST(YieldValues, EqualTheLinearizedModesAtEveryPoint) {
  const Model m = jointed_blocks();
  const std::vector<YieldPoint> points = make_yield_points(m);
  const std::vector<PlasticState> states = some_states(points.size());
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m.n_dofs()) * 1e-4;
  const YieldEvaluator evaluator(m, points);
  YieldValues values;
  double scale = 0.0;
  evaluator.evaluate(states, u, values, &scale);
  ASSERT_EQ(values.first.size(), points.size() + 1);
  double expected_scale = 0.0;
  int blocks = 0;
  int supports = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Eigen::VectorXd stress = local_stress(m, points[p], states[p], u);
    const LocalYield y = linearize(m, points[p], states[p], stress);
    ASSERT_EQ(values.modes(p), y.f.size());
    const double size = y.f.cwiseAbs().maxCoeff() + (y.a * stress).cwiseAbs().maxCoeff();
    EXPECT_LE((values.of(p) - y.f).cwiseAbs().maxCoeff(), 1e-12 * size) << "point " << p;
    expected_scale = std::max(
        {expected_scale, stress.cwiseAbs().maxCoeff(), (y.f - y.a * stress).cwiseAbs().maxCoeff()});
    blocks += points[p].is_interface() ? 0 : 1;
    supports += points[p].is_interface() && points[p].block_j == kGround ? 1 : 0;
  }
  EXPECT_NEAR(scale, expected_scale, 1e-12 * expected_scale);
  EXPECT_GT(blocks, 0);
  EXPECT_GT(supports, 0);
}

TEST(YieldValues, ChangeLinearlyWithTheDisplacements) {
  const Model m = jointed_blocks();
  const std::vector<YieldPoint> points = make_yield_points(m);
  const std::vector<PlasticState> states = some_states(points.size());
  const Eigen::VectorXd u = Eigen::VectorXd::Random(m.n_dofs()) * 1e-4;
  const Eigen::VectorXd du = Eigen::VectorXd::Random(m.n_dofs()) * 3e-5;
  const YieldEvaluator evaluator(m, points);
  YieldValues before;
  YieldValues after;
  evaluator.evaluate(states, u, before);
  evaluator.evaluate(states, Eigen::VectorXd(u + du), after);
  for (std::size_t p = 0; p < points.size(); ++p) {
    const Eigen::VectorXd stress = local_stress(m, points[p], states[p], u);
    const LocalYield y = linearize(m, points[p], states[p], stress);
    const Eigen::VectorXd df = y.a * local_stiffness(m, points[p]) * local_strain(m, points[p], du);
    const double size = df.cwiseAbs().maxCoeff() + y.f.cwiseAbs().maxCoeff();
    EXPECT_LE((after.of(p) - before.of(p) - df).cwiseAbs().maxCoeff(), 1e-10 * size)
        << "point " << p;
  }
}

}  // namespace
}  // namespace bimrock
