// rebuild_model: the materials, loads, monitors and stages of a changed case on the geometry of
// a built model equal what build_model makes of the changed case from scratch, and a change that
// would need a new geometry is refused, naming the item.
#include <gtest/gtest.h>

#include <bimrock/model/model.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

// Four blocks on a roller base (one support of each kind), a jointed pair and a continuum pair.
CaseSpec wall() {
  CaseSpec c;
  c.file = "case.yaml";
  c.block_materials = {testing::rock(10e9, 0.2, 2.5e4)};
  c.joint_materials = {testing::springs("joint", 1e10, 5e9), testing::continuum(100.0)};
  c.blocks = testing::blocks_of(brick_pattern(2, 2, 1.0, 1.0, Stagger::none));
  c.default_joint = "joint";
  c.joint_rules.push_back({testing::with_orientation(90.0), "continuum", {0, "joints.rules[0]"}});
  c.supports.push_back(testing::fixed({0, 0}, {1, 0}));
  c.supports.push_back(testing::roller({1, 0}, {2, 0}));
  c.loads.gravity = {0.0, -1.0};
  c.loads.points.push_back({{1.5, 1.5}, {1e3, 0.0}, {0, "loads.points[0]"}});
  c.monitors.push_back({"top", {0.5, 1.5}, {0, "monitors[0]"}});
  return c;
}

void expect_same(const Model& a, const Model& b) {
  ASSERT_EQ(a.n_blocks(), b.n_blocks());
  ASSERT_EQ(a.n_interfaces(), b.n_interfaces());
  for (int k = 0; k < a.n_blocks(); ++k)
    EXPECT_EQ(a.blocks[k].material, b.blocks[k].material);
  for (int f = 0; f < a.n_interfaces(); ++f) {
    EXPECT_EQ(a.interfaces[f].joint_material, b.interfaces[f].joint_material) << f;
    EXPECT_EQ(a.interfaces[f].normal_stiffness, b.interfaces[f].normal_stiffness) << f;
    EXPECT_EQ(a.interfaces[f].shear_stiffness, b.interfaces[f].shear_stiffness) << f;
  }
  ASSERT_EQ(a.block_materials.size(), b.block_materials.size());
  for (std::size_t m = 0; m < a.block_materials.size(); ++m) {
    EXPECT_EQ(a.block_materials[m].young, b.block_materials[m].young);
    EXPECT_EQ(a.block_materials[m].unit_weight, b.block_materials[m].unit_weight);
  }
  ASSERT_EQ(a.joint_materials.size(), b.joint_materials.size());
  EXPECT_EQ(a.loads.gravity, b.loads.gravity);
  ASSERT_EQ(a.loads.points.size(), b.loads.points.size());
  for (std::size_t p = 0; p < a.loads.points.size(); ++p) {
    EXPECT_EQ(a.loads.points[p].block, b.loads.points[p].block);
    EXPECT_EQ(a.loads.points[p].force, b.loads.points[p].force);
  }
  ASSERT_EQ(a.monitors.size(), b.monitors.size());
  for (std::size_t m = 0; m < a.monitors.size(); ++m)
    EXPECT_EQ(a.monitors[m].block, b.monitors[m].block);
  ASSERT_EQ(a.stages.size(), b.stages.size());
}

TEST(RebuildModel, NewMaterialsAndLoadsGiveTheModelBuiltFromScratch) {
  const Model built = build_model(wall());
  CaseSpec changed = wall();
  changed.block_materials[0].young = 30e9;  // the continuum's penalty springs follow E
  changed.joint_materials[0].normal_stiffness = 4e10;
  changed.joint_materials[1].penalty_factor = 10.0;
  changed.settings.penalty_factor = 50.0;  // the rigid support's springs
  changed.loads.points[0] = {{0.5, 0.5}, {0.0, -2e3}, {0, "loads.points[0]"}};
  changed.monitors[0].point = {1.5, 0.5};
  StageSpec stage;
  stage.name = "push";
  stage.increments = 3;
  stage.loads.points.push_back({{1.5, 1.5}, {5e3, 0.0}, {0, "stages[0].loads.points[0]"}});
  stage.source = {0, "stages[0]"};
  changed.stages.push_back(stage);
  const Model rebuilt = rebuild_model(built, changed);
  const Model scratch = build_model(changed);
  expect_same(rebuilt, scratch);
  // ... and not the model it started from.
  EXPECT_NE(rebuilt.interfaces[0].normal_stiffness, built.interfaces[0].normal_stiffness);
  EXPECT_NE(rebuilt.loads.points[0].block, built.loads.points[0].block);
}

TEST(RebuildModel, TheIntactRockOfAGeneratedModelKeepsItsPlace) {
  // A continuum material the builder adds itself (cuts through intact rock of a domain) is the
  // last joint material, after the case's; a rebuild adds it again with the new penalty factor.
  CaseSpec c = wall();
  Model built = build_model(c);
  JointMaterial intact = testing::continuum(c.settings.penalty_factor);
  intact.name = "intact rock (continuum)";
  built.joint_materials.push_back(intact);
  c.settings.penalty_factor = 7.0;
  const Model rebuilt = rebuild_model(built, c);
  ASSERT_EQ(rebuilt.joint_materials.size(), built.joint_materials.size());
  EXPECT_EQ(rebuilt.joint_materials.back().name, intact.name);
  EXPECT_EQ(rebuilt.joint_materials.back().penalty_factor, 7.0);
}

TEST(RebuildModel, AChangeOfTheGeometryIsRefusedNamingTheItem) {
  const Model built = build_model(wall());
  CaseSpec renamed = wall();
  renamed.block_materials[0].name = "granite";
  for (BlockSpec& b : renamed.blocks)
    b.material = "granite";
  try {
    (void)rebuild_model(built, renamed);
    FAIL() << "a renamed material was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.item(), "materials.rock");
    EXPECT_NE(e.message().find("build a new model"), std::string::npos) << e.message();
  }
  CaseSpec finer = wall();
  finer.joint_materials[0].subdivisions = 2;
  try {
    (void)rebuild_model(built, finer);
    FAIL() << "new subdivisions were accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.item(), "joint");
  }
}

}  // namespace
}  // namespace bimrock
