// Water in the joints: the pore pressure of a phreatic surface and of pressure lines, the block
// faces it wets, and the loads it makes, checked against closed forms (hydrostatics,
// Archimedes) and a second integration written here (the midpoint rule on fine pieces).
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/model/water_pressure.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr double kWater = 9810.0;

TEST(WaterPressure, PhreaticPressureIsHydrostaticBelowTheSurfaceOnly) {
  const std::vector<Vec2> surface = {{0, 10}, {10, 20}, {20, 20}};
  EXPECT_DOUBLE_EQ(phreatic_pressure(surface, kWater, {5, 0}), kWater * 15.0);
  EXPECT_DOUBLE_EQ(phreatic_pressure(surface, kWater, {5, 16}), 0.0);
  EXPECT_DOUBLE_EQ(phreatic_pressure(surface, kWater, {-7, 4}), kWater * 6.0);  // level beyond
  EXPECT_DOUBLE_EQ(phreatic_pressure(surface, kWater, {35, 19}), kWater * 1.0);
  EXPECT_DOUBLE_EQ(phreatic_pressure({}, kWater, {0, -100}), 0.0);
}

// Blocks [0, 1] x [0, 1] and [1, 2] x [0, 1] on a support along y = 0, joined by `joint`.
CaseSpec two_blocks(const JointMaterial& joint) {
  CaseSpec c;
  c.file = "water";
  c.block_materials = {testing::rock(10e9, 0.2, 2e4)};
  c.joint_materials = {joint};
  c.blocks = testing::blocks_of(
      {Polygon{{{0, 0}, {1, 0}, {1, 1}, {0, 1}}}, Polygon{{{1, 0}, {2, 0}, {2, 1}, {1, 1}}}});
  c.default_joint = joint.name;
  c.supports.push_back(testing::fixed({0, 0}, {2, 0}));
  return c;
}

WaterSpec level(double y) {
  WaterSpec w;
  w.surface = {{-5, y}, {5, y}};
  return w;
}

// The water's generalized forces on block k (eq. 14 with the pressure as a traction).
Eigen::Matrix<double, 6, 1> water_load(const Model& m, const WaterSpec& w, int k) {
  Loads loads;
  loads.water = water_faces(m, w);
  return assemble_loads(m, loads).segment<6>(6 * k);
}

TEST(WaterPressure, ASubmergedBlockFeelsArchimedesBuoyancy) {
  const Model m = build_model(two_blocks(testing::springs("joint", 1e9, 1e9)));
  for (const double y : {3.0, 0.5}) {  // submerged; half submerged
    const double submerged = std::min(y, 1.0);
    for (const int k : {0, 1}) {
      const auto f = water_load(m, level(y), k);
      EXPECT_NEAR(f(0), 0.0, 1e-9 * kWater);
      EXPECT_NEAR(f(1), kWater * submerged, 1e-9 * kWater) << "block " << k << " under y = " << y;
      EXPECT_NEAR(f(2), 0.0, 1e-9 * kWater);  // about the centroid: the faces' pressures balance
    }
  }
}

TEST(WaterPressure, IntactRockIsImpermeableSoContinuumInterfacesStayDry) {
  // A continuum interface between the blocks: the left block feels the water on its left face
  // only, gamma_w (h - 1/2) per metre for a surface at h above its top.
  const Model m = build_model(two_blocks(testing::continuum(1e7)));
  const double h = 2.5;
  EXPECT_NEAR(water_load(m, level(h), 0)(0), kWater * (h - 0.5), 1e-9 * kWater);
  EXPECT_NEAR(water_load(m, level(h), 1)(0), -kWater * (h - 0.5), 1e-9 * kWater);
}

// The resultant force and moment (about the centroid) of -p n over the block's outline by the
// midpoint rule on 20 000 pieces per edge, p from the definition of the phreatic surface.
Eigen::Vector3d midpoint_rule(const Polygon& poly, const std::vector<Vec2>& surface) {
  const auto height = [&](double x) {
    if (x <= surface.front().x())
      return surface.front().y();
    for (std::size_t k = 1; k < surface.size(); ++k) {
      if (x <= surface[k].x()) {
        const Vec2 a = surface[k - 1], b = surface[k];
        return a.y() + (x - a.x()) * (b.y() - a.y()) / (b.x() - a.x());
      }
    }
    return surface.back().y();
  };
  Vec2 centroid = Vec2::Zero();
  for (const Vec2& v : poly.vertices)
    centroid += v / static_cast<double>(poly.vertices.size());  // a parallelogram's centroid
  Eigen::Vector3d out = Eigen::Vector3d::Zero();
  const int pieces = 20000;
  for (std::size_t e = 0; e < poly.vertices.size(); ++e) {
    const Vec2 a = poly.vertices[e], b = poly.vertices[(e + 1) % poly.vertices.size()];
    const Vec2 n = Vec2(b.y() - a.y(), a.x() - b.x()).normalized();
    const double ds = (b - a).norm() / pieces;
    for (int i = 0; i < pieces; ++i) {
      const Vec2 x = a + (i + 0.5) / pieces * (b - a);
      const double p = kWater * std::max(0.0, height(x.x()) - x.y());
      const Vec2 f = -p * ds * n;
      out.head<2>() += f;
      out(2) += cross(x - centroid, f);
    }
  }
  return out;
}

TEST(WaterPressure, ASlopingSurfaceAcrossABlockMatchesADirectIntegration) {
  CaseSpec c = two_blocks(testing::springs("joint", 1e9, 1e9));
  const Polygon shear{{{0, 0}, {1, 0}, {1.4, 1.2}, {0.4, 1.2}}};  // a parallelogram
  c.blocks = testing::blocks_of({shear});
  c.supports = {testing::fixed({0, 0}, {1, 0})};
  const Model m = build_model(c);
  WaterSpec w;
  w.surface = {{-1, 0.3}, {0.7, 0.9}, {1.2, 1.5}, {3, 1.1}};  // crosses the block's faces
  const auto f = water_load(m, w, 0);
  const Eigen::Vector3d expected = midpoint_rule(shear, w.surface);
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(f(i), expected(i), 1e-6 * kWater) << i;
}

TEST(WaterPressure, APressureLineReplacesThePhreaticPressureWhereItLies) {
  const Model m = build_model(two_blocks(testing::springs("joint", 1e9, 1e9)));
  WaterSpec w = level(3.0);
  const double u = 1e3;  // [Pa] along the base of both blocks
  w.lines.push_back({{0, 0}, {2, 0}, u, u, {0, "lines[0]"}});
  // Up: u on the base, down: gamma_w (3 - 1) on the top; the sides balance.
  for (const int k : {0, 1})
    EXPECT_NEAR(water_load(m, w, k)(1), u - kWater * 2.0, 1e-9 * kWater);
}

TEST(WaterPressure, APressureLineOnNoFaceIsRefusedByName) {
  const Model m = build_model(two_blocks(testing::springs("joint", 1e9, 1e9)));
  WaterSpec w;
  w.lines.push_back({{0, 0.5}, {2, 0.7}, 1e3, 1e3, {7, "loads.water.lines[0]"}});
  try {
    water_faces(m, w);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 7);
    EXPECT_EQ(e.item(), "loads.water.lines[0]");
    EXPECT_NE(e.message().find("lies on no wet block face"), std::string::npos);
  }
}

// Stage water replaces the water in force: the stages' loads add up to the last water's alone.
TEST(WaterPressure, EachStagesWaterReplacesTheWaterBefore) {
  CaseSpec c = two_blocks(testing::springs("joint", 1e9, 1e9));
  for (const double y : {2.0, 0.4, -1.0}) {  // -1: a stage without water
    StageSpec st{"water " + std::to_string(y), {}, 1, std::nullopt, {0, "stages[]"}};
    if (y > 0.0)
      st.loads.water = level(y);
    c.stages.push_back(st);
  }
  const Model m = build_model(c);
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(m.n_dofs());
  for (const Stage& st : m.stages)
    sum += assemble_loads(m, st.loads);
  Loads last;
  last.water = water_faces(m, level(0.4));
  const Eigen::VectorXd expected = assemble_loads(m, last);
  EXPECT_LT((sum - expected).norm(), 1e-9 * expected.norm());
  EXPECT_EQ(m.stages[2].loads.water_surface, level(0.4).surface);  // the last stage had none
}

}  // namespace
}  // namespace bimrock
