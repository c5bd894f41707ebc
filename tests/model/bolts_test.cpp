// Bolts resolved into springs on a column of three blocks 2 m wide, stacked with horizontal
// joints at y = 1 and y = 2.5: block 0 is [0, 2] x [0, 1], block 1 [0, 2] x [1, 2.5], block 2
// [0, 2] x [2.5, 4.5]. The crossing points are worked by hand: the line from (0.5, 0.25) along
// (1, 4) meets y = 1 at t = 0.75 / 4 = 0.1875, x = 0.6875, and y = 2.5 at t = 2.25 / 4 = 0.5625,
// x = 1.0625. Every refusal names the bolt's item and the line of its key.
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/bolts.hpp>

namespace bimrock {
namespace {

// Line numbers matter: the bolts' list starts on line 19, after `bolts:` on line 18.
const std::string kColumnHead = R"(schema: 1
analysis: {thickness: 2.0}
materials:
  rock: {E: 10.0e9, nu: 0.2, unit_weight: 26.0e3}
joint_materials:
  joint: {kn: 1.0e10, ks: 5.0e9}
blocks:
  - {material: rock, vertices: [[0, 0], [2, 0], [2, 1], [0, 1]]}
  - {material: rock, vertices: [[0, 1], [2, 1], [2, 2.5], [0, 2.5]]}
  - {material: rock, vertices: [[0, 2.5], [2, 2.5], [2, 4.5], [0, 4.5]]}
joints: {default: joint}
supports:
  - {line: [[0, 0], [2, 0]]}
)";

// Stage 1 installs the bolts that name it; stage 2 excavates the top block.
const std::string kColumnStages = R"(stages:
  - {name: in situ, loads: {gravity: [0, -1]}}
  - {name: support}
  - {name: top removed, excavate: {blocks: [2]}}
)";

CaseSpec column_with_bolts(const std::string& bolts, const std::string& stages = kColumnStages) {
  return read_case_string(kColumnHead + stages + "bolts:\n" + bolts, "case.yaml").spec;
}

// "line: item: message" of the InputError that building the model throws ("" if it builds).
std::string bolt_error_of(const CaseSpec& spec) {
  try {
    build_model(spec);
  } catch (const InputError& e) {
    return std::to_string(e.line()) + ": " + e.item() + ": " + e.message();
  }
  return "";
}

// One bolt in flow style (on line 19): the line from (0.5, 0.25) to (1.5, 4.25) through the three
// blocks, with `more` keys.
std::string through_column(const std::string& kind, const std::string& more = "") {
  return "  - {kind: " + kind +
         ", from: [0.5, 0.25], to: [1.5, 4.25], axial_stiffness: 5.0e7, capacity: 2.5e5" + more +
         "}\n";
}

void expect_point(const Vec2& p, double x, double y) {
  EXPECT_DOUBLE_EQ(p.x(), x);
  EXPECT_DOUBLE_EQ(p.y(), y);
}

TEST(Bolts, AnAnchoredBoltJoinsItsHeadBlockToItsFarEndBlock) {
  // Head at the top, far end at the bottom: block 2 to block 0.
  const Model m = build_model(column_with_bolts(
      "  - {kind: anchored, from: [1.5, 4.25], to: [0.5, 0.25], axial_stiffness: 5.0e7, "
      "capacity: 2.5e5, pretension: 1.0e5}\n"));
  ASSERT_EQ(m.bolts.size(), 1u);
  ASSERT_EQ(m.bolt_springs.size(), 1u);
  const BoltSpring& s = m.bolt_springs[0];
  EXPECT_EQ(s.bolt, 0);
  EXPECT_EQ(s.block_a, 2);
  EXPECT_EQ(s.block_b, 0);
  expect_point(s.a, 1.5, 4.25);
  expect_point(s.b, 0.5, 0.25);
  EXPECT_NEAR(s.axis.x(), -1.0 / std::sqrt(17.0), 1e-15);
  EXPECT_NEAR(s.axis.y(), -4.0 / std::sqrt(17.0), 1e-15);
  const Bolt& b = m.bolts[0];
  EXPECT_EQ(b.name, "bolt 0");
  EXPECT_EQ(b.kind, BoltSpec::Kind::anchored);
  EXPECT_EQ(b.axial_stiffness, 5.0e7);
  EXPECT_EQ(b.capacity, 2.5e5);
  EXPECT_EQ(b.pretension, 1.0e5);
  EXPECT_EQ(b.shear_stiffness, 0.0);
  EXPECT_FALSE(b.shear_capacity.has_value());
  EXPECT_EQ(b.stage, 0);
  EXPECT_EQ(b.source.item, "bolts[0]");
  EXPECT_EQ(b.source.line, 19);
}

TEST(Bolts, AnAnchoredBoltFromTheBottomStartsInTheBottomBlock) {
  const Model m = build_model(column_with_bolts(through_column("anchored")));
  ASSERT_EQ(m.bolt_springs.size(), 1u);
  EXPECT_EQ(m.bolt_springs[0].block_a, 0);
  EXPECT_EQ(m.bolt_springs[0].block_b, 2);
  expect_point(m.bolt_springs[0].a, 0.5, 0.25);
  expect_point(m.bolt_springs[0].b, 1.5, 4.25);
  EXPECT_NEAR(m.bolt_springs[0].axis.x(), 1.0 / std::sqrt(17.0), 1e-15);
  EXPECT_NEAR(m.bolt_springs[0].axis.y(), 4.0 / std::sqrt(17.0), 1e-15);
}

TEST(Bolts, AGroutedBoltHasASpringAtEachJointItCrosses) {
  const Model m = build_model(column_with_bolts(
      through_column("grouted", ", shear_stiffness: 1.0e7, shear_capacity: 1.0e5, name: rb")));
  ASSERT_EQ(m.bolt_springs.size(), 2u);
  const BoltSpring& lower = m.bolt_springs[0];
  EXPECT_EQ(lower.block_a, 0);
  EXPECT_EQ(lower.block_b, 1);
  expect_point(lower.a, 0.6875, 1.0);
  expect_point(lower.b, 0.6875, 1.0);
  const BoltSpring& upper = m.bolt_springs[1];
  EXPECT_EQ(upper.block_a, 1);
  EXPECT_EQ(upper.block_b, 2);
  expect_point(upper.a, 1.0625, 2.5);
  expect_point(upper.b, 1.0625, 2.5);
  EXPECT_NEAR(upper.axis.x(), 1.0 / std::sqrt(17.0), 1e-15);
  EXPECT_NEAR(upper.axis.y(), 4.0 / std::sqrt(17.0), 1e-15);
  const Bolt& b = m.bolts[0];
  EXPECT_EQ(b.name, "rb");
  EXPECT_EQ(b.shear_stiffness, 1.0e7);
  EXPECT_EQ(b.shear_capacity, 1.0e5);
}

TEST(Bolts, AGroutedBoltFromFaceToFaceFollowsTheLineDownwards) {
  // From (2, 4.25) on block 2's right face to (0, 0.25) on block 0's left face, along (-2, -4):
  // y = 2.5 at t = 1.75 / 4 = 0.4375, x = 2 - 0.875 = 1.125; y = 1 at t = 3.25 / 4 = 0.8125,
  // x = 2 - 1.625 = 0.375.
  const Model m = build_model(column_with_bolts(
      "  - {kind: grouted, from: [2, 4.25], to: [0, 0.25], axial_stiffness: 5.0e7, capacity: "
      "2.5e5}\n"));
  ASSERT_EQ(m.bolt_springs.size(), 2u);
  EXPECT_EQ(m.bolt_springs[0].block_a, 2);
  EXPECT_EQ(m.bolt_springs[0].block_b, 1);
  expect_point(m.bolt_springs[0].a, 1.125, 2.5);
  EXPECT_EQ(m.bolt_springs[1].block_a, 1);
  EXPECT_EQ(m.bolt_springs[1].block_b, 0);
  expect_point(m.bolt_springs[1].a, 0.375, 1.0);
}

TEST(Bolts, SpringsFollowTheirBoltsInOrder) {
  const Model m = build_model(
      column_with_bolts(through_column("grouted") + through_column("anchored", ", name: b")));
  ASSERT_EQ(m.bolts.size(), 2u);
  ASSERT_EQ(m.bolt_springs.size(), 3u);
  EXPECT_EQ(m.bolt_springs[0].bolt, 0);
  EXPECT_EQ(m.bolt_springs[1].bolt, 0);
  EXPECT_EQ(m.bolt_springs[2].bolt, 1);
  EXPECT_EQ(m.bolts[1].name, "b");
  EXPECT_EQ(m.bolts[1].source.item, "bolts[1]");
}

TEST(Bolts, PerModelIsTheThicknessOverTheSpacing) {
  const Model m = build_model(column_with_bolts(through_column("anchored", ", spacing: 0.5") +
                                                through_column("anchored") +
                                                through_column("anchored", ", spacing: 1.6")));
  EXPECT_EQ(m.bolts[0].per_model, 4.0);  // 2 m / 0.5 m
  EXPECT_EQ(m.bolts[1].per_model, 1.0);  // one bolt in the thickness
  EXPECT_DOUBLE_EQ(m.bolts[2].per_model, 1.25);
}

TEST(Bolts, IsInstalledAtTheStageItNames) {
  const Model m = build_model(column_with_bolts(through_column("grouted", ", install: support") +
                                                through_column("anchored")));
  EXPECT_EQ(m.bolts[0].stage, 1);
  EXPECT_EQ(m.bolts[1].stage, 0);  // the first stage by default
}

TEST(Bolts, SpringsArePresentFromTheirStageWhileTheirBlocksAre) {
  // Grouted, installed at stage 1: springs 0 (blocks 0-1) and 1 (blocks 1-2); anchored, at stage
  // 0: spring 2 (blocks 0-2). Stage 2 excavates block 2.
  const Model m = build_model(column_with_bolts(through_column("grouted", ", install: support") +
                                                through_column("anchored")));
  ASSERT_EQ(m.bolt_springs.size(), 3u);
  using Present = std::vector<char>;
  EXPECT_EQ(springs_present(m, -1), (Present{0, 0, 0}));
  EXPECT_EQ(springs_present(m, 0), (Present{0, 0, 1}));
  EXPECT_EQ(springs_present(m, 1), (Present{1, 1, 1}));
  EXPECT_EQ(springs_present(m, 2), (Present{1, 0, 0}));
  EXPECT_THROW(springs_present(m, 3), std::out_of_range);
  EXPECT_THROW(springs_present(m, -2), std::out_of_range);
}

TEST(Bolts, NoBoltsLeaveTheModelAsItWas) {
  const Model m = build_model(read_case_string(kColumnHead + kColumnStages, "case.yaml").spec);
  EXPECT_TRUE(m.bolts.empty());
  EXPECT_TRUE(m.bolt_springs.empty());
  EXPECT_TRUE(springs_present(m, 0).empty());
}

TEST(Bolts, RebuildResolvesTheBoltsAgain) {
  const Model built = build_model(read_case_string(kColumnHead + kColumnStages, "case.yaml").spec);
  const Model m = rebuild_model(built, column_with_bolts(through_column("grouted")));
  ASSERT_EQ(m.bolt_springs.size(), 2u);
  expect_point(m.bolt_springs[1].a, 1.0625, 2.5);
}

TEST(Bolts, AStageInstallingABlockHoldsItsBoltsBack) {
  // Block 2 is installed by stage 1: absent at stage 0, the line leaves the rock at y = 2.5.
  const std::string stages = R"(stages:
  - {name: in situ, loads: {gravity: [0, -1]}}
  - {name: support, install: {blocks: [2]}}
  - {name: top removed, excavate: {blocks: [2]}}
)";
  EXPECT_EQ(bolt_error_of(column_with_bolts(through_column("grouted"), stages)),
            "19: bolts[0]: leaves the blocks present at its installation (stages[0] 'in situ') "
            "between (1.0625, 2.5) and (1.5, 4.25): a bolt runs inside the rock from its head to "
            "its far end");
  EXPECT_EQ(build_model(column_with_bolts(through_column("grouted", ", install: support"), stages))
                .bolt_springs.size(),
            2u);
}

// Refusals: what bolts.hpp lists, each naming the bolt's item or key at its line.

TEST(Bolts, RejectsBoltsWithoutStages) {
  CaseSpec c = column_with_bolts(through_column("anchored"));
  c.stages.clear();
  EXPECT_EQ(bolt_error_of(c),
            "19: bolts[0]: a bolt is installed at the start of a stage: give stages (an elastic "
            "analysis has no bolts)");
}

TEST(Bolts, RejectsAnInstallThatNamesNoStage) {
  EXPECT_EQ(bolt_error_of(column_with_bolts(through_column("anchored", ", install: lining"))),
            "19: bolts[0].install: no stage is named 'lining': give the name of the stage at "
            "whose start the bolt is installed");
}

TEST(Bolts, RejectsAnInstallThatNamesTwoStages) {
  const std::string stages = R"(stages:
  - {name: in situ, loads: {gravity: [0, -1]}}
  - {name: support}
  - {name: support}
)";
  EXPECT_EQ(
      bolt_error_of(column_with_bolts(through_column("anchored", ", install: support"), stages)),
      "19: bolts[0].install: names two stages, stages[1] and stages[2] ('support'): give the "
      "stages distinct names");
}

TEST(Bolts, RejectsNumbersOutOfTheirRanges) {
  const struct {
    std::string kind;
    std::string more;
    std::string error;
  } cases[] = {
      {"anchored", ", pretension: -1",
       "bolts[0].pretension: must lie in [0, capacity) = [0, 250000) N (a bolt tensioned to its "
       "capacity has yielded), not -1"},
      {"anchored", ", pretension: 2.5e5",
       "bolts[0].pretension: must lie in [0, capacity) = [0, 250000) N (a bolt tensioned to its "
       "capacity has yielded), not 250000"},
      {"anchored", ", shear_stiffness: -1",
       "bolts[0].shear_stiffness: must be a number >= 0 (the bolt's shear stiffness, N/m; 0 or "
       "left out: the bolt carries no shear), not -1"},
      {"anchored", ", shear_stiffness: 1.0e7, shear_capacity: 0",
       "bolts[0].shear_capacity: must be a positive number (the bolt's shear capacity, N), not "
       "0"},
      {"anchored", ", spacing: 0",
       "bolts[0].spacing: must be a positive number (the out-of-plane spacing of the bolts, m), "
       "not 0"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.more);
    EXPECT_EQ(bolt_error_of(column_with_bolts(through_column(c.kind, c.more))), "19: " + c.error);
  }
}

TEST(Bolts, RejectsAStiffnessOrCapacityThatIsNotPositive) {
  // Line by line, so that the line of the offending key is seen.
  const std::string bolt = R"(  - kind: anchored
    from: [0.5, 0.25]
    to: [1.5, 4.25]
    axial_stiffness: 0
    capacity: -2.0e5
)";
  EXPECT_EQ(bolt_error_of(column_with_bolts(bolt)),
            "22: bolts[0].axial_stiffness: must be a positive number (the bolt's axial stiffness, "
            "N/m), not 0");
  std::string positive_stiffness = bolt;
  positive_stiffness.replace(positive_stiffness.find("stiffness: 0"), 12, "stiffness: 5.0e7");
  EXPECT_EQ(bolt_error_of(column_with_bolts(positive_stiffness)),
            "23: bolts[0].capacity: must be a positive number (the bolt's tensile capacity, N), "
            "not -200000");
}

TEST(Bolts, RejectsNumbersThatAreNotFinite) {
  // A spec made in code, not read: the reader refuses these first.
  CaseSpec c = column_with_bolts(through_column("anchored"));
  c.bolts[0].axial_stiffness = std::numeric_limits<double>::infinity();
  EXPECT_EQ(bolt_error_of(c),
            "19: bolts[0].axial_stiffness: must be a positive number (the bolt's axial stiffness, "
            "N/m), not inf");
  c = column_with_bolts(through_column("anchored"));
  c.bolts[0].to.x() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(bolt_error_of(c), "19: bolts[0].to: must be a finite point [x, y]");
}

TEST(Bolts, RejectsAPretensionedGroutedBolt) {
  EXPECT_EQ(bolt_error_of(column_with_bolts(through_column("grouted", ", pretension: 1.0e5"))),
            "19: bolts[0].pretension: a grouted bolt is bonded along its length and cannot be "
            "pretensioned: leave pretension out, or make the bolt anchored");
}

TEST(Bolts, RejectsAShearCapacityWithoutAShearStiffness) {
  EXPECT_EQ(bolt_error_of(column_with_bolts(through_column("grouted", ", shear_capacity: 1.0e5"))),
            "19: bolts[0].shear_capacity: is given without a shear stiffness: give "
            "shear_stiffness (N/m) too, or leave shear_capacity out");
}

TEST(Bolts, RejectsAHeadAtTheFarEnd) {
  EXPECT_EQ(bolt_error_of(column_with_bolts(
                "  - {kind: anchored, from: [0.5, 0.25], to: [0.5, 0.25], axial_stiffness: 5.0e7, "
                "capacity: 2.5e5}\n")),
            "19: bolts[0].to: coincides with the head 'from': a bolt runs from its head to its "
            "far end, a distinct point");
}

TEST(Bolts, RejectsALineThatLeavesTheRock) {
  // Straight up from (0.5, 0.25) to (0.5, 5.25): out of block 2's top at y = 4.5.
  EXPECT_EQ(bolt_error_of(column_with_bolts(
                "  - {kind: anchored, from: [0.5, 0.25], to: [0.5, 5.25], axial_stiffness: 5.0e7, "
                "capacity: 2.5e5}\n")),
            "19: bolts[0]: leaves the blocks present at its installation (stages[0] 'in situ') "
            "between (0.5, 4.5) and (0.5, 5.25): a bolt runs inside the rock from its head to its "
            "far end");
  // Its head in the air below the column: out from (0.5, -1) to (0.5, 0).
  EXPECT_EQ(bolt_error_of(column_with_bolts(
                "  - {kind: anchored, from: [0.5, -1], to: [0.5, 4], axial_stiffness: 5.0e7, "
                "capacity: 2.5e5}\n")),
            "19: bolts[0]: leaves the blocks present at its installation (stages[0] 'in situ') "
            "between (0.5, -1) and (0.5, 0): a bolt runs inside the rock from its head to its "
            "far end");
}

TEST(Bolts, RejectsALineThroughAnExcavatedBlock) {
  // Installed after the top block is excavated: the line leaves the rock at y = 2.5.
  EXPECT_EQ(bolt_error_of(column_with_bolts(through_column("grouted", ", install: top removed"))),
            "19: bolts[0]: leaves the blocks present at its installation (stages[2] 'top "
            "removed') between (1.0625, 2.5) and (1.5, 4.25): a bolt runs inside the rock from "
            "its head to its far end");
}

TEST(Bolts, RejectsALineAlongAJoint) {
  EXPECT_EQ(bolt_error_of(column_with_bolts(
                "  - {kind: grouted, from: [0.5, 1], to: [1.5, 1], axial_stiffness: 5.0e7, "
                "capacity: 2.5e5}\n")),
            "19: bolts[0]: runs along a joint, between block 0 and block 1 from (0.5, 1) to "
            "(1.5, 1): a bolt crosses the joints it meets");
}

TEST(Bolts, RejectsALineWithinOneBlock) {
  EXPECT_EQ(bolt_error_of(column_with_bolts(
                "  - {kind: anchored, from: [0.5, 0.25], to: [1.5, 0.75], axial_stiffness: 5.0e7, "
                "capacity: 2.5e5}\n")),
            "19: bolts[0]: lies within block 0: it crosses no joint, so it would join the block "
            "to itself");
}

}  // namespace
}  // namespace bimrock
