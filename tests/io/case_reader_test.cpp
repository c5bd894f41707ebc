// The case-file reader fills a CaseSpec with every value, default and source line, and rejects
// bad input with an InputError that names the line and the item.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include <bimrock/io/case_reader.hpp>

namespace bimrock {
namespace {

using ::testing::HasSubstr;

// Line numbers matter: the tests below check them.
const std::string kFullCase = R"(schema: 1
title: "Two blocks"
analysis:
  plane: stress
  thickness: 0.5
  penalty_factor: 1.0e6
materials:
  granite: {E: 89.0e9, nu: 0.26, unit_weight: 26.0e3}
  soft: {E: 1.0e9, nu: 0.3}
joint_materials:
  vertical: {kn: 395.9e9, ks: 438.8e9, subdivisions: 4}
  clay: {E: 1.0e9, nu: 0.25, h: 0.01}
  glue: {continuum: true}
  stiff_glue: {continuum: true, penalty_factor: 1.0e8, integration: lobatto}
blocks:
  - {material: granite, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
  - material: soft
    vertices:
      - [1, 0]
      - [2, 0]
      - [2, 1]
      - [1, 1]
joints:
  default: vertical
  rules:
    - {material: clay, orientation: 90, tolerance: 2}
    - {material: glue, line: [[1, 0], [1, 1]]}
    - {material: stiff_glue, box: [[0.5, 0], [1.5, 1]]}
supports:
  - {line: [[0, 0], [2, 0]]}
  - {box: [[1.9, 0], [2.1, 1]], type: roller, joint: vertical}
loads:
  gravity: [0, -1]
  points:
    - {at: [1.5, 0.5], force: [1000, 0]}
  tractions:
    - {line: [[0, 1], [2, 1]], normal: -1.0e6, shear: 2.0e5}
    - {box: [[0, 0], [0, 1]], normal: 5.0e5}
monitors:
  - {name: A, at: [1.0, 0.5]}
output:
  vtk: false
)";

// The smallest valid case; the block is on line 7. Tests append sections to it.
const std::string kMinimal = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2}
joint_materials:
  joint: {kn: 1.0e10, ks: 1.0e10}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
)";

struct ReadFailure {
  int line = -1;
  std::string item;
  std::string message;
};

ReadFailure read_failure_of(const std::string& text) {
  try {
    read_case_string(text, "case.yaml");
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), "case.yaml");
    return {e.line(), e.item(), e.message()};
  }
  ADD_FAILURE() << "no InputError for:\n" << text;
  return {};
}

// ---- A valid case -------------------------------------------------------------------------------

TEST(CaseReader, ReadsTitleAndAnalysisSettings) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  EXPECT_EQ(c.spec.file, "full.yaml");
  EXPECT_EQ(c.spec.title, "Two blocks");
  EXPECT_EQ(c.spec.settings.plane, PlaneMode::stress);
  EXPECT_DOUBLE_EQ(c.spec.settings.thickness, 0.5);
  EXPECT_DOUBLE_EQ(c.spec.settings.penalty_factor, 1.0e6);
}

TEST(CaseReader, ReadsThePlasticAnalysisOptionsAndTheirDefaults) {
  const Case given = read_case_string(kMinimal +
                                          "analysis: {bracket_tolerance: 1.0e-3, "
                                          "max_bisections: 12, max_rounds: 7, "
                                          "yield_tolerance: 1.0e-8}\n",
                                      "case.yaml");
  EXPECT_DOUBLE_EQ(given.plastic.bracket_tolerance, 1.0e-3);
  EXPECT_EQ(given.plastic.max_bisections, 12);
  EXPECT_EQ(given.plastic.max_rounds, 7);
  EXPECT_DOUBLE_EQ(given.plastic.yield_tolerance, 1.0e-8);
  const Case defaults = read_case_string(kMinimal, "case.yaml");
  EXPECT_DOUBLE_EQ(defaults.plastic.bracket_tolerance, PlasticOptions{}.bracket_tolerance);
  EXPECT_EQ(defaults.plastic.max_bisections, PlasticOptions{}.max_bisections);
}

TEST(CaseReader, ReadsTheFactorOfSafetySectionAndResolvesItsMaterials) {
  const std::string base = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2}
joint_materials:
  weak: {kn: 1.0e9, ks: 1.0e9, friction: 30}
  glue: {kn: 1.0e9, ks: 1.0e9}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
stages: [{name: gravity, loads: {gravity: [0, -1]}}]
)";
  const Case c = read_case_string(base +
                                      "factor_of_safety: {materials: [weak], tolerance: 2.0e-3, "
                                      "step: 0.1, largest: 4}\n",
                                  "case.yaml");
  ASSERT_TRUE(c.plastic.factor_of_safety.has_value());
  const FactorOfSafetyOptions& f = *c.plastic.factor_of_safety;
  EXPECT_DOUBLE_EQ(f.tolerance, 2.0e-3);
  EXPECT_DOUBLE_EQ(f.step, 0.1);
  EXPECT_DOUBLE_EQ(f.largest, 4.0);
  ASSERT_EQ(f.selection.joint_materials.size(), 2u);
  EXPECT_EQ(f.selection.joint_materials[0], 1);  // weak
  EXPECT_EQ(f.selection.joint_materials[1], 0);  // glue
  EXPECT_EQ(f.selection.block_materials, std::vector<char>(1, 0));

  const ReadFailure elastic = read_failure_of(base + "factor_of_safety: {materials: [glue]}\n");
  EXPECT_EQ(elastic.item, "factor_of_safety.materials[0]");
  EXPECT_NE(elastic.message.find("no strength"), std::string::npos) << elastic.message;
  const ReadFailure unknown = read_failure_of(base + "factor_of_safety: {materials: [granite]}\n");
  EXPECT_NE(unknown.message.find("neither a material nor a joint material"), std::string::npos);
  const ReadFailure without_stages = read_failure_of(kMinimal + "factor_of_safety: {}\n");
  EXPECT_EQ(without_stages.item, "factor_of_safety");
}

TEST(CaseReader, ASeismicLoadAddsItsCoefficientsToTheBodyForce) {
  const Case c = read_case_string(kMinimal +
                                      "stages:\n  - name: quake\n    loads: {gravity: [0, "
                                      "-1], seismic: {kh: 0.15, kv: -0.05}}\n",
                                  "case.yaml");
  const Vec2 g = c.spec.stages.at(0).loads.gravity;
  EXPECT_DOUBLE_EQ(g.x(), 0.15);
  EXPECT_DOUBLE_EQ(g.y(), -1.0 + 0.05);  // kv < 0 acts upwards
  const ReadFailure f = read_failure_of(kMinimal + "loads: {seismic: {kh: 3}}\n");
  EXPECT_EQ(f.item, "loads.seismic.kh");
}

TEST(CaseReader, ReadsWaterWithItsSurfaceAndPressureLines) {
  const Case c = read_case_string(
      kMinimal +
          "loads:\n  water:\n    surface: [[0, 2], [5, 3]]\n    unit_weight: 1.0e4\n"
          "    lines:\n      - {from: [0, 0], to: [1, 0], pressure: [100, 0]}\n",
      "case.yaml");
  const WaterSpec& w = c.spec.loads.water.value();
  ASSERT_EQ(w.surface.size(), 2u);
  EXPECT_EQ(w.surface[1], Vec2(5, 3));
  EXPECT_DOUBLE_EQ(w.unit_weight, 1e4);
  ASSERT_EQ(w.lines.size(), 1u);
  EXPECT_DOUBLE_EQ(w.lines[0].pressure_from, 100.0);
  EXPECT_DOUBLE_EQ(w.lines[0].pressure_to, 0.0);
  EXPECT_EQ(w.lines[0].source.item, "loads.water.lines[0]");
  EXPECT_DOUBLE_EQ(
      read_case_string(kMinimal + "loads: {water: {surface: [[0, 1], [1, 1]]}}\n", "case.yaml")
          .spec.loads.water->unit_weight,
      9810.0);
}

TEST(CaseReaderErrors, BadWaterIsRejectedByItem) {
  const struct {
    std::string water;
    std::string item;
    std::string message;
  } cases[] = {
      {"{surface: [[0, 1], [0, 2]]}", "loads.water.surface[1]", "the surface's x must increase"},
      {"{surface: [[0, 1]]}", "loads.water.surface", "needs at least two points"},
      {"{unit_weight: 9810}", "loads.water", "give a phreatic surface, pressure lines or both"},
      {"{surface: [[0, 1], [1, 1]], unit_weight: 0}", "loads.water.unit_weight", "positive"},
      {"{lines: [{from: [0, 0], to: [1, 0], pressure: [-1, 0]}]}",
       "loads.water.lines[0].pressure[0]", "must not be negative"},
      {"{lines: [{from: [0, 0], to: [1, 0], pressure: [1]}]}", "loads.water.lines[0].pressure",
       "must be [p_from, p_to]"},
      {"{lines: [{from: [0, 0], to: [0, 0], pressure: [1, 1]}]}", "loads.water.lines[0].to",
       "must differ"},
      {"{lines: [{from: [0, 0], to: [1, 0], pressure: [1, 1], depth: 2}]}",
       "loads.water.lines[0].depth", ""},
  };
  for (const auto& w : cases) {
    const ReadFailure f = read_failure_of(kMinimal + "loads:\n  water: " + w.water + "\n");
    EXPECT_EQ(f.line, 9) << w.water;
    EXPECT_EQ(f.item, w.item) << w.water << ": " << f.message;
    EXPECT_NE(f.message.find(w.message), std::string::npos) << f.message;
  }
}

TEST(CaseReaderErrors, PlasticAnalysisOptionsOutOfRangeAreRejected) {
  const ReadFailure wide = read_failure_of(kMinimal + "analysis: {bracket_tolerance: 0.6}\n");
  EXPECT_EQ(wide.item, "analysis.bracket_tolerance");
  EXPECT_NE(wide.message.find("at most 0.5"), std::string::npos) << wide.message;
  const ReadFailure none = read_failure_of(kMinimal + "analysis: {max_bisections: 0}\n");
  EXPECT_EQ(none.item, "analysis.max_bisections");
  EXPECT_NE(none.message.find("from 1 to 200"), std::string::npos) << none.message;
}

TEST(CaseReader, ReadsBlockMaterialsInFileOrderWithTheirLines) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  ASSERT_EQ(c.spec.block_materials.size(), 2u);
  const BlockMaterial& g = c.spec.block_materials[0];
  EXPECT_EQ(g.name, "granite");
  EXPECT_DOUBLE_EQ(g.young, 89.0e9);
  EXPECT_DOUBLE_EQ(g.poisson, 0.26);
  EXPECT_DOUBLE_EQ(g.unit_weight, 26.0e3);
  EXPECT_EQ(g.source.line, 8);
  EXPECT_EQ(g.source.item, "materials.granite");
  EXPECT_DOUBLE_EQ(c.spec.block_materials[1].unit_weight, 0.0);  // default
}

TEST(CaseReader, ReadsTheThreeFormsOfJointMaterial) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  ASSERT_EQ(c.spec.joint_materials.size(), 4u);
  const JointMaterial& springs = c.spec.joint_materials[0];
  EXPECT_EQ(springs.name, "vertical");
  EXPECT_EQ(springs.kind, JointMaterial::Kind::springs);
  EXPECT_DOUBLE_EQ(springs.normal_stiffness, 395.9e9);
  EXPECT_DOUBLE_EQ(springs.shear_stiffness, 438.8e9);
  EXPECT_EQ(springs.integration, Integration::lobatto);
  EXPECT_EQ(springs.subdivisions, 4);
  EXPECT_EQ(springs.source.line, 11);
  EXPECT_EQ(springs.source.item, "joint_materials.vertical");

  // A layer is turned into springs by eq. 7, in the plane mode of the analysis (stress here).
  const JointMaterial& layer = c.spec.joint_materials[1];
  const SpringPair k = layer_stiffness(1.0e9, 0.25, 0.01, PlaneMode::stress);
  EXPECT_EQ(layer.kind, JointMaterial::Kind::springs);
  EXPECT_DOUBLE_EQ(layer.normal_stiffness, k.normal);
  EXPECT_DOUBLE_EQ(layer.shear_stiffness, k.shear);
  EXPECT_DOUBLE_EQ(layer.shear_stiffness, 1.0e9 / (2.0 * 1.25 * 0.01));
  EXPECT_EQ(layer.integration, Integration::lobatto);
  EXPECT_EQ(layer.subdivisions, 1);

  // A continuum takes the analysis' penalty factor and Gauss integration unless told otherwise.
  const JointMaterial& glue = c.spec.joint_materials[2];
  EXPECT_EQ(glue.kind, JointMaterial::Kind::continuum);
  EXPECT_DOUBLE_EQ(glue.penalty_factor, 1.0e6);
  EXPECT_EQ(glue.integration, Integration::gauss);
  const JointMaterial& stiff = c.spec.joint_materials[3];
  EXPECT_DOUBLE_EQ(stiff.penalty_factor, 1.0e8);
  EXPECT_EQ(stiff.integration, Integration::lobatto);
}

TEST(CaseReader, ReadsBlocksInFlowAndBlockStyleWithTheirLines) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  ASSERT_EQ(c.spec.blocks.size(), 2u);
  const BlockSpec& b0 = c.spec.blocks[0];
  EXPECT_EQ(b0.material, "granite");
  ASSERT_EQ(b0.polygon.size(), 4u);
  EXPECT_EQ(b0.polygon.vertices[2], Vec2(1, 1));
  EXPECT_EQ(b0.source.line, 16);
  EXPECT_EQ(b0.source.item, "blocks[0]");
  const BlockSpec& b1 = c.spec.blocks[1];
  EXPECT_EQ(b1.material, "soft");
  ASSERT_EQ(b1.polygon.size(), 4u);
  EXPECT_EQ(b1.polygon.vertices[3], Vec2(1, 1));
  EXPECT_EQ(b1.source.line, 17);
  EXPECT_EQ(b1.source.item, "blocks[1]");
}

TEST(CaseReader, ReadsJointRulesAsSelectorsInOrder) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  EXPECT_EQ(c.spec.default_joint, "vertical");
  ASSERT_EQ(c.spec.joint_rules.size(), 3u);
  const JointRule& by_angle = c.spec.joint_rules[0];
  EXPECT_EQ(by_angle.material, "clay");
  EXPECT_EQ(by_angle.where.kind, Selector::Kind::orientation);
  EXPECT_DOUBLE_EQ(by_angle.where.angle_deg, 90.0);
  EXPECT_DOUBLE_EQ(by_angle.where.angle_tolerance_deg, 2.0);
  EXPECT_EQ(by_angle.source.line, 26);
  EXPECT_EQ(by_angle.source.item, "joints.rules[0]");
  const JointRule& by_line = c.spec.joint_rules[1];
  EXPECT_EQ(by_line.where.kind, Selector::Kind::line);
  EXPECT_EQ(by_line.where.line.a, Vec2(1, 0));
  EXPECT_EQ(by_line.where.line.b, Vec2(1, 1));
  EXPECT_EQ(by_line.where.source.item, "joints.rules[1].line");
  const JointRule& by_box = c.spec.joint_rules[2];
  EXPECT_EQ(by_box.where.kind, Selector::Kind::box);
  EXPECT_EQ(by_box.where.box.lo, Vec2(0.5, 0));
  EXPECT_EQ(by_box.where.box.hi, Vec2(1.5, 1));
}

TEST(CaseReader, ReadsSupportsWithDefaultsAndTheirLines) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  ASSERT_EQ(c.spec.supports.size(), 2u);
  const SupportSpec& fixed = c.spec.supports[0];
  EXPECT_EQ(fixed.kind, SupportKind::fixed);  // default
  EXPECT_FALSE(fixed.joint_material.has_value());
  EXPECT_EQ(fixed.where.kind, Selector::Kind::line);
  EXPECT_EQ(fixed.source.line, 30);
  EXPECT_EQ(fixed.source.item, "supports[0]");
  const SupportSpec& roller = c.spec.supports[1];
  EXPECT_EQ(roller.kind, SupportKind::roller);
  EXPECT_EQ(roller.joint_material, "vertical");
  EXPECT_EQ(roller.where.kind, Selector::Kind::box);
  EXPECT_EQ(roller.source.line, 31);
}

TEST(CaseReader, ReadsLoadsMonitorsAndOutput) {
  const Case c = read_case_string(kFullCase, "full.yaml");
  const LoadsSpec& loads = c.spec.loads;
  EXPECT_EQ(loads.gravity, Vec2(0, -1));
  ASSERT_EQ(loads.points.size(), 1u);
  EXPECT_EQ(loads.points[0].point, Vec2(1.5, 0.5));
  EXPECT_EQ(loads.points[0].force, Vec2(1000, 0));
  EXPECT_EQ(loads.points[0].source.line, 35);
  EXPECT_EQ(loads.points[0].source.item, "loads.points[0]");
  ASSERT_EQ(loads.tractions.size(), 2u);
  EXPECT_DOUBLE_EQ(loads.tractions[0].normal, -1.0e6);
  EXPECT_DOUBLE_EQ(loads.tractions[0].shear, 2.0e5);
  EXPECT_EQ(loads.tractions[0].where.kind, Selector::Kind::line);
  EXPECT_DOUBLE_EQ(loads.tractions[1].shear, 0.0);  // default
  EXPECT_EQ(loads.tractions[1].where.kind, Selector::Kind::box);
  EXPECT_EQ(loads.tractions[1].source.line, 38);
  EXPECT_TRUE(c.spec.stages.empty());

  ASSERT_EQ(c.spec.monitors.size(), 1u);
  EXPECT_EQ(c.spec.monitors[0].name, "A");
  EXPECT_EQ(c.spec.monitors[0].point, Vec2(1.0, 0.5));
  EXPECT_EQ(c.spec.monitors[0].source.line, 40);

  EXPECT_FALSE(c.output.vtk);
  EXPECT_TRUE(c.output.csv);  // default
}

TEST(CaseReader, FillsDefaultsForAMinimalCase) {
  const Case c = read_case_string(kMinimal, "case.yaml");
  EXPECT_EQ(c.spec.title, "");
  EXPECT_EQ(c.spec.settings.plane, PlaneMode::strain);
  EXPECT_DOUBLE_EQ(c.spec.settings.thickness, 1.0);
  EXPECT_DOUBLE_EQ(c.spec.settings.penalty_factor, kDefaultPenaltyFactor);
  EXPECT_EQ(c.spec.default_joint, "");
  EXPECT_TRUE(c.spec.joint_rules.empty());
  EXPECT_TRUE(c.spec.supports.empty());
  EXPECT_EQ(c.spec.loads.gravity, Vec2::Zero());
  EXPECT_TRUE(c.output.vtk);
  EXPECT_TRUE(c.output.csv);
  EXPECT_EQ(c.spec.blocks.at(0).source.line, 7);
}

TEST(CaseReader, ContinuumTakesThePenaltyFactorOfTheAnalysisWhateverTheKeyOrder) {
  // joint_materials before analysis in the file: the plane mode and penalty still apply.
  const Case c = read_case_string(kMinimal +
                                      "analysis: {penalty_factor: 3.0e5, plane: strain}\n"
                                      "joints: {default: joint}\n",
                                  "case.yaml");
  EXPECT_DOUBLE_EQ(c.spec.settings.penalty_factor, 3.0e5);
  const Case d = read_case_string(R"(schema: 1
joint_materials:
  glue: {continuum: true}
analysis: {penalty_factor: 3.0e5}
materials:
  rock: {E: 10.0e9, nu: 0.2}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
)",
                                  "case.yaml");
  EXPECT_DOUBLE_EQ(d.spec.joint_materials.at(0).penalty_factor, 3.0e5);
}

TEST(CaseReader, ReadsTheExampleCaseFiles) {
  const std::string folder = std::string(BIMROCK_SOURCE_DIR) + "/examples/jointed_rock_mass/";
  for (const char* name : {"case1_vertical.yaml", "case2_horizontal.yaml", "case3_biaxial.yaml"}) {
    const Case c = read_case_file(folder + name);
    EXPECT_EQ(c.spec.file, folder + name);
    EXPECT_EQ(c.spec.blocks.size(), 105u) << name;  // 10 x 10 with every other column staggered
    EXPECT_EQ(c.spec.joint_rules.at(0).where.kind, Selector::Kind::orientation) << name;
    EXPECT_EQ(c.spec.supports.at(0).kind, SupportKind::roller) << name;
  }
}

// ---- Bad input: each names its line and item ---------------------------------------------------

TEST(CaseReaderErrors, MalformedYamlGivesTheParserLine) {
  const ReadFailure f =
      read_failure_of("schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2\nblocks: []\n");
  EXPECT_EQ(f.line, 4);
  EXPECT_EQ(f.item, "");
  EXPECT_THAT(f.message, HasSubstr("malformed YAML"));
}

TEST(CaseReaderErrors, MissingSchemaNamesTheFirstKey) {
  const ReadFailure f = read_failure_of(kMinimal.substr(std::string("schema: 1\n").size()));
  EXPECT_EQ(f.line, 1);
  EXPECT_EQ(f.item, "schema");
  EXPECT_THAT(f.message, HasSubstr("'schema: 1'"));
  EXPECT_THAT(f.message, HasSubstr("found 'materials'"));
}

TEST(CaseReaderErrors, SchemaThatIsNotTheFirstKeyIsRejected) {
  const ReadFailure f = read_failure_of("title: x\nschema: 1\n");
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.item, "schema");
  EXPECT_THAT(f.message, HasSubstr("first key"));
}

TEST(CaseReaderErrors, SchemaOtherThanTheInteger1IsRejected) {
  ReadFailure f = read_failure_of("schema: 2\n");
  EXPECT_EQ(f.line, 1);
  EXPECT_EQ(f.item, "schema");
  EXPECT_THAT(f.message, HasSubstr("unsupported version 2"));
  f = read_failure_of("schema: 1.0\n");
  EXPECT_EQ(f.item, "schema");
  EXPECT_THAT(f.message, HasSubstr("whole number"));
}

TEST(CaseReaderErrors, EmptyFileIsRejected) {
  const ReadFailure f = read_failure_of("# nothing but a comment\n");
  EXPECT_EQ(f.line, 0);
  EXPECT_THAT(f.message, HasSubstr("empty"));
}

TEST(CaseReaderErrors, UnknownTopLevelKeyIsNamedWithItsLine) {
  const ReadFailure f = read_failure_of(kMinimal + "matrials: {}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "matrials");
  EXPECT_THAT(f.message, HasSubstr("unknown key 'matrials'"));
  EXPECT_THAT(f.message, HasSubstr("materials"));  // lists what is allowed
}

TEST(CaseReaderErrors, UnknownNestedKeyIsNamedWithItsLine) {
  ReadFailure f =
      read_failure_of(kMinimal + "  - {material: rock, vertixes: [[1, 0], [2, 0], [2, 1]]}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "blocks[1].vertixes");
  EXPECT_THAT(f.message, HasSubstr("unknown key 'vertixes' (allowed here: material, vertices)"));
  f = read_failure_of(kMinimal + "analysis:\n  plane: strain\n  thicknes: 2\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_EQ(f.item, "analysis.thicknes");
}

TEST(CaseReaderErrors, OrientationIsUnknownInASupport) {
  const ReadFailure f = read_failure_of(kMinimal + "supports:\n  - {orientation: 0}\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_EQ(f.item, "supports[0].orientation");
  EXPECT_THAT(f.message, HasSubstr("unknown key"));
}

TEST(CaseReaderErrors, DuplicateKeyIsRejectedWithBothLines) {
  ReadFailure f = read_failure_of(kMinimal + "materials:\n  other: {E: 1.0e9, nu: 0.2}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "materials");
  EXPECT_THAT(f.message, HasSubstr("given twice (first on line 2)"));
  f = read_failure_of(kMinimal + "joints: {default: joint, default: joint}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "joints.default");
  // A material name given twice is a repeated key too.
  f = read_failure_of(
      "schema: 1\nmaterials:\n  rock: {E: 1.0e9, nu: 0.2}\n  rock: {E: 2.0e9, nu: 0.2}\n");
  EXPECT_EQ(f.line, 4);
  EXPECT_EQ(f.item, "materials.rock");
}

TEST(CaseReaderErrors, MissingRequiredKeyIsNamedAtItsMap) {
  ReadFailure f = read_failure_of(kMinimal + "  - {vertices: [[1, 0], [2, 0], [2, 1]]}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "blocks[1].material");
  EXPECT_THAT(f.message, HasSubstr("required key 'material' is missing"));
  f = read_failure_of("schema: 1\nmaterials:\n  rock:\n    nu: 0.2\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "materials.rock.E");
  f = read_failure_of(kMinimal +
                      "loads:\n  tractions:\n    - {line: [[0, 1], [1, 1]], shear: 1}\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_EQ(f.item, "loads.tractions[0].normal");
}

TEST(CaseReaderErrors, MissingRequiredSectionIsReportedAfterErrorsInsideSections) {
  ReadFailure f = read_failure_of("schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2}\n");
  EXPECT_EQ(f.line, 0);
  EXPECT_EQ(f.item, "blocks");
  // The NaN on line 5 comes first, though blocks are missing too.
  f = read_failure_of(
      "schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2}\njoint_materials:\n"
      "  joint: {kn: .nan, ks: 1.0e10}\n");
  EXPECT_EQ(f.line, 5);
  EXPECT_EQ(f.item, "joint_materials.joint.kn");
}

TEST(CaseReaderErrors, WrongTypesAreRejected) {
  ReadFailure f = read_failure_of("schema: 1\nmaterials:\n  rock: {E: ten, nu: 0.2}\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "materials.rock.E");
  EXPECT_THAT(f.message, HasSubstr("must be a number, not 'ten'"));
  // A quoted number is a string in YAML.
  f = read_failure_of("schema: 1\nmaterials:\n  rock: {E: \"10\", nu: 0.2}\n");
  EXPECT_EQ(f.item, "materials.rock.E");
  EXPECT_THAT(f.message, HasSubstr("string"));
  // A point that is not a list of two numbers.
  f = read_failure_of(kMinimal + "  - {material: rock, vertices: [[1, 0], [2, 0, 0], [2, 1]]}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "blocks[1].vertices[1]");
  EXPECT_THAT(f.message, HasSubstr("point [x, y]"));
  // A map where a list is expected.
  f = read_failure_of(kMinimal + "supports: {line: [[0, 0], [1, 0]]}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "supports");
  EXPECT_THAT(f.message, HasSubstr("must be a list"));
  // A list where a map is expected.
  f = read_failure_of(kMinimal + "analysis: [strain]\n");
  EXPECT_EQ(f.item, "analysis");
  EXPECT_THAT(f.message, HasSubstr("must be a map"));
  // A value left out.
  f = read_failure_of(kMinimal + "analysis:\n  thickness:\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_EQ(f.item, "analysis.thickness");
  EXPECT_THAT(f.message, HasSubstr("missing"));
  // Not a boolean.
  f = read_failure_of(kMinimal + "output: {vtk: 2}\n");
  EXPECT_EQ(f.item, "output.vtk");
  EXPECT_THAT(f.message, HasSubstr("true or false"));
  // A segment that is not two points.
  f = read_failure_of(kMinimal + "supports:\n  - {line: [[0, 0], [1, 0], [2, 0]]}\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_EQ(f.item, "supports[0].line");
}

TEST(CaseReaderErrors, NaNIsNotAFiniteNumber) {
  const ReadFailure f = read_failure_of("schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: .nan}\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "materials.rock.nu");
  EXPECT_THAT(f.message, HasSubstr("must be a finite number"));
}

TEST(CaseReaderErrors, InfinityIsNotAFiniteNumber) {
  ReadFailure f = read_failure_of(kMinimal + "loads:\n  gravity: [0, -.inf]\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_EQ(f.item, "loads.gravity[1]");
  EXPECT_THAT(f.message, HasSubstr("must be a finite number"));
  f = read_failure_of("schema: 1\nmaterials:\n  rock: {E: .inf, nu: 0.2}\n");
  EXPECT_EQ(f.item, "materials.rock.E");
  EXPECT_THAT(f.message, HasSubstr("must be a finite number"));
}

TEST(CaseReaderErrors, UnknownEnumValuesListTheAllowedOnes) {
  ReadFailure f = read_failure_of(kMinimal + "analysis: {plane: strian}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "analysis.plane");
  EXPECT_THAT(f.message, HasSubstr("unknown value 'strian' (allowed: strain, stress)"));
  f = read_failure_of(kMinimal + "supports:\n  - {line: [[0, 0], [1, 0]], type: pinned}\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_EQ(f.item, "supports[0].type");
  EXPECT_THAT(f.message, HasSubstr("allowed: fixed, roller"));
  f = read_failure_of("schema: 1\njoint_materials:\n  j: {kn: 1, ks: 1, integration: simpson}\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "joint_materials.j.integration");
  EXPECT_THAT(f.message, HasSubstr("allowed: lobatto, gauss"));
}

TEST(CaseReaderErrors, SelectorWithTwoKindsIsRejected) {
  ReadFailure f = read_failure_of(kMinimal +
                                  "joints:\n  rules:\n    - {material: joint, orientation: 0, "
                                  "line: [[0, 0], [1, 0]]}\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_EQ(f.item, "joints.rules[0]");
  EXPECT_THAT(f.message, HasSubstr("only one of line, box, orientation or group"));
  f = read_failure_of(kMinimal +
                      "supports:\n  - {line: [[0, 0], [1, 0]], box: [[0, 0], [1, 1]]}\n");
  EXPECT_EQ(f.item, "supports[0]");
  EXPECT_THAT(f.message, HasSubstr("only one of line, box or group"));
}

TEST(CaseReaderErrors, SelectorWithNoKindIsRejected) {
  const ReadFailure f = read_failure_of(kMinimal + "supports:\n  - {type: roller}\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_EQ(f.item, "supports[0]");
  EXPECT_THAT(f.message, HasSubstr("give one of line, box or group"));
}

TEST(CaseReaderErrors, BoxWithCornersSwappedIsRejected) {
  const ReadFailure f = read_failure_of(kMinimal +
                                        "loads:\n  tractions:\n    - {box: [[1, 1], [0, 0]], "
                                        "normal: 1}\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_EQ(f.item, "loads.tractions[0].box");
  EXPECT_THAT(f.message, HasSubstr("lower-left"));
}

TEST(CaseReaderErrors, ToleranceWithoutOrientationIsRejected) {
  const ReadFailure f = read_failure_of(kMinimal +
                                        "joints:\n  rules:\n    - {material: joint, line: "
                                        "[[0, 0], [1, 0]], tolerance: 2}\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_EQ(f.item, "joints.rules[0].tolerance");
}

TEST(CaseReaderErrors, ThicknessMustBePositive) {
  ReadFailure f = read_failure_of(kMinimal + "analysis: {thickness: 0}\n");
  EXPECT_EQ(f.line, 8);
  EXPECT_EQ(f.item, "analysis.thickness");
  EXPECT_THAT(f.message, HasSubstr("must be positive"));
  f = read_failure_of(kMinimal + "analysis: {thickness: -1.0}\n");
  EXPECT_EQ(f.item, "analysis.thickness");
}

TEST(CaseReaderErrors, SubdivisionsMustBeAWholeNumberOfAtLeastOne) {
  ReadFailure f =
      read_failure_of("schema: 1\njoint_materials:\n  j: {kn: 1, ks: 1, subdivisions: 0}\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "joint_materials.j.subdivisions");
  EXPECT_THAT(f.message, HasSubstr("at least 1"));
  f = read_failure_of("schema: 1\njoint_materials:\n  j: {kn: 1, ks: 1, subdivisions: 2.5}\n");
  EXPECT_EQ(f.item, "joint_materials.j.subdivisions");
  EXPECT_THAT(f.message, HasSubstr("whole number"));
}

TEST(CaseReaderErrors, JointMaterialMixingFormsIsRejected) {
  ReadFailure f =
      read_failure_of("schema: 1\njoint_materials:\n  j: {kn: 1.0e10, ks: 1.0e10, E: 1.0e9}\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "joint_materials.j");
  EXPECT_THAT(f.message, HasSubstr("mixes forms"));
  f = read_failure_of("schema: 1\njoint_materials:\n  j: {continuum: true, kn: 1.0e10}\n");
  EXPECT_EQ(f.item, "joint_materials.j");
  EXPECT_THAT(f.message, HasSubstr("mixes forms"));
}

TEST(CaseReaderErrors, JointMaterialOfNoFormOrIncompleteFormIsRejected) {
  ReadFailure f = read_failure_of("schema: 1\njoint_materials:\n  j: {subdivisions: 2}\n");
  EXPECT_EQ(f.line, 3);
  EXPECT_EQ(f.item, "joint_materials.j");
  EXPECT_THAT(f.message, HasSubstr("give kn and ks"));
  f = read_failure_of("schema: 1\njoint_materials:\n  j: {kn: 1.0e10}\n");
  EXPECT_EQ(f.item, "joint_materials.j.ks");
  f = read_failure_of("schema: 1\njoint_materials:\n  j: {E: 1.0e9, nu: 0.2, h: 0}\n");
  EXPECT_EQ(f.item, "joint_materials.j.h");
  EXPECT_THAT(f.message, HasSubstr("must be positive"));
  f = read_failure_of("schema: 1\njoint_materials:\n  j: {kn: 1, ks: 1, penalty_factor: 10}\n");
  EXPECT_EQ(f.item, "joint_materials.j.penalty_factor");
  EXPECT_THAT(f.message, HasSubstr("only to continuum"));
}

TEST(CaseReaderErrors, EmptyMaterialsOrBlocksAreRejected) {
  ReadFailure f = read_failure_of("schema: 1\nmaterials: {}\n");
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.item, "materials");
  f = read_failure_of("schema: 1\nmaterials:\n  rock: {E: 1.0e9, nu: 0.2}\nblocks: []\n");
  EXPECT_EQ(f.line, 4);
  EXPECT_EQ(f.item, "blocks");
}

TEST(CaseReaderErrors, MonitorNamesMustBeUnique) {
  const ReadFailure f = read_failure_of(kMinimal +
                                        "monitors:\n  - {name: A, at: [0, 0]}\n"
                                        "  - {name: A, at: [1, 1]}\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_EQ(f.item, "monitors[1].name");
  EXPECT_THAT(f.message, HasSubstr("monitors[0] (line 9)"));
}

TEST(CaseReaderErrors, MoreThanOneDocumentIsRejected) {
  const ReadFailure f = read_failure_of(kMinimal + "---\nschema: 1\n");
  EXPECT_EQ(f.line, 9);
  EXPECT_THAT(f.message, HasSubstr("more than one YAML document"));
}

TEST(CaseReaderErrors, ASecondDocumentAfterAnEndMarkerIsRejected) {
  const ReadFailure f = read_failure_of(kMinimal + "...\n# a comment\nschema: 1\n");
  EXPECT_EQ(f.line, 10);
  EXPECT_THAT(f.message, HasSubstr("more than one YAML document"));
}

TEST(CaseReaderErrors, ALeadingDocumentMarkerIsOneDocument) {
  EXPECT_NO_THROW(read_case_string("%YAML 1.2\n---\n" + kMinimal + "...\n# end\n", "c.yaml"));
}

TEST(CaseReaderErrors, AFileOfOnlyACommaIsMalformed) {
  // yaml-cpp 0.7's LoadAll never returns on this input; the reader must not call it.
  const ReadFailure f = read_failure_of("# a comment\n,\n");
  EXPECT_EQ(f.line, 2);
  EXPECT_THAT(f.message, HasSubstr("malformed YAML"));
}

TEST(CaseReaderErrors, TextThatIsNotUtf8IsNamed) {
  const ReadFailure f = read_failure_of(
      "schema: 1\ntitle: \"Mauer \xFC"
      "ber Fels\"\n" +
      kMinimal.substr(10));
  EXPECT_EQ(f.line, 2);
  EXPECT_EQ(f.item, "title");
  EXPECT_THAT(f.message, HasSubstr("not valid UTF-8 (byte 0xFC at position 7)"));
  // Well-formed UTF-8 (u-umlaut as 0xC3 0xBC) is read as written.
  const Case c = read_case_string(
      "schema: 1\ntitle: \"Mauer \xC3\xBC"
      "ber Fels\"\n" +
          kMinimal.substr(10),
      "case.yaml");
  EXPECT_EQ(c.spec.title,
            "Mauer \xC3\xBC"
            "ber Fels");
}

TEST(CaseReaderErrors, UnreadableFileIsNamedWithLineZero) {
  const std::string missing = "/nonexistent/bimrock/case.yaml";
  try {
    read_case_file(missing);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), missing);
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(e.item(), "");
    EXPECT_THAT(e.what(), HasSubstr(missing));
    EXPECT_THAT(e.message(), HasSubstr("cannot open"));
  }
  const std::string folder = ::testing::TempDir();
  try {
    read_case_file(folder);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 0);
    EXPECT_THAT(e.message(), HasSubstr("folder"));
  }
}

TEST(CaseReaderErrors, ErrorsFromAFileCarryItsName) {
  const std::filesystem::path path =
      std::filesystem::path(::testing::TempDir()) / "case_reader_test_bad.yaml";
  std::ofstream(path) << kMinimal << "analysis: {thickness: 0}\n";
  try {
    read_case_file(path.string());
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.file(), path.string());
    EXPECT_EQ(e.line(), 8);
    EXPECT_EQ(std::string(e.what()), path.string() + ":8: analysis.thickness: must be positive");
  }
  std::filesystem::remove(path);
}

}  // namespace
}  // namespace bimrock
