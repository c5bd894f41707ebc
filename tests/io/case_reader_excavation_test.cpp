// The case file's initial stress and the stages' excavate, install and release: the values read
// into the spec, and each bad input named by file, line and item. The blocks are six unit
// squares in two rows of three, numbered row by row from the bottom left, so block k has its
// centroid at (k % 3 + 0.5, k / 3 + 0.5).
#include <gtest/gtest.h>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/model.hpp>

#include "support/read_error.hpp"

namespace bimrock {
namespace {

const std::string kSixBlockCase = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2, unit_weight: 26.0e3}
  shotcrete: {E: 20.0e9, nu: 0.2, unit_weight: 24.0e3}
joint_materials:
  joint: {kn: 1.0e10, ks: 1.0e10}
joints: {default: joint}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
  - {material: rock, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}
  - {material: rock, vertices: [[2, 0], [3, 0], [3, 1], [2, 1]]}
  - {material: rock, vertices: [[0, 1], [1, 1], [1, 2], [0, 2]]}
  - {material: rock, vertices: [[1, 1], [2, 1], [2, 2], [1, 2]]}
  - {material: shotcrete, vertices: [[2, 1], [3, 1], [3, 2], [2, 2]]}
supports:
  - {line: [[0, 0], [3, 0]]}
)";  // 16 lines: what is appended starts on line 17

const std::string kOneStage = "stages:\n  - {name: in situ, loads: {gravity: [0, -1]}}\n";

using testing::read_error_of;

// Reads and builds: the builder's checks, with the reader's lines and items.
std::string build_error_of(const std::string& text) {
  try {
    build_model(read_case_string(text, "case.yaml").spec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(CaseReaderExcavation, ReadsTheInitialStress) {
  const Case c = read_case_string(kSixBlockCase + R"(initial_stress:
  stress: [-1.0e6, -2.0e6, 0.5e6]
  gravity: {ground_level: 120.0, unit_weight: 26.0e3, k0: 0.5}
  allow_yield: true
)" + kOneStage,
                                  "case.yaml");
  ASSERT_TRUE(c.spec.initial_stress.has_value());
  const InitialStressSpec& s = *c.spec.initial_stress;
  EXPECT_EQ(s.uniform, Eigen::Vector3d(-1e6, -2e6, 0.5e6));
  ASSERT_TRUE(s.gravity.has_value());
  EXPECT_EQ(s.gravity->ground_level, 120.0);
  EXPECT_EQ(s.gravity->unit_weight, 26e3);
  EXPECT_EQ(s.gravity->k0, 0.5);
  EXPECT_TRUE(s.allow_yield);
  EXPECT_EQ(s.source.line, 17);
  EXPECT_EQ(s.source.item, "initial_stress");
}

TEST(CaseReaderExcavation, InitialStressDefaultsToNoUniformPartAndNoYield) {
  const Case gravity_only = read_case_string(
      kSixBlockCase + "initial_stress: {gravity: {ground_level: 2, unit_weight: 1.0e4, k0: 0}}\n" +
          kOneStage,
      "case.yaml");
  EXPECT_EQ(gravity_only.spec.initial_stress->uniform, Eigen::Vector3d::Zero());
  EXPECT_EQ(gravity_only.spec.initial_stress->gravity->k0, 0.0);
  EXPECT_FALSE(gravity_only.spec.initial_stress->allow_yield);
  const Case stress_only = read_case_string(
      kSixBlockCase + "initial_stress: {stress: [0, -1.0e5, 0]}\n" + kOneStage, "case.yaml");
  EXPECT_FALSE(stress_only.spec.initial_stress->gravity.has_value());
  EXPECT_EQ(stress_only.spec.initial_stress->uniform, Eigen::Vector3d(0, -1e5, 0));
  EXPECT_FALSE(read_case_string(kSixBlockCase + kOneStage, "case.yaml").spec.initial_stress);
}

TEST(CaseReaderExcavation, RejectsAnInitialStressWithoutStages) {
  EXPECT_EQ(read_error_of(kSixBlockCase +
                          "loads: {gravity: [0, -1]}\ninitial_stress: {stress: [0, -1, 0]}\n"),
            "case.yaml:18: initial_stress: is the stress in the rock before the first stage: "
            "give stages (an elastic analysis, with loads, starts unstressed)");
}

struct BadInput {
  const char* name;
  std::string text;      // appended to kSixBlockCase
  std::string expected;  // the whole message
};

class BadInitialStress : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInitialStress, IsNamedByFileLineAndItem) {
  EXPECT_EQ(read_error_of(kSixBlockCase + GetParam().text + kOneStage), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    CaseReaderExcavation, BadInitialStress,
    ::testing::Values(
        BadInput{"neither_part", "initial_stress: {allow_yield: true}\n",
                 "case.yaml:17: initial_stress: give the stress, its gravitational part or both "
                 "(stress, gravity)"},
        BadInput{"two_components", "initial_stress:\n  stress: [-1.0e6, -1.0e6]\n",
                 "case.yaml:18: initial_stress.stress: must be [sigma_xx, sigma_yy, tau_xy], "
                 "three stresses in Pa (tension positive)"},
        BadInput{"not_a_number", "initial_stress:\n  stress: [0, .nan, 0]\n",
                 "case.yaml:18: initial_stress.stress[1]: must be a finite number, not '.nan'"},
        BadInput{"too_large", "initial_stress:\n  stress: [0, 0, -2.0e15]\n",
                 "case.yaml:18: initial_stress.stress[2]: must be at most 1e+15 Pa in magnitude "
                 "(larger loads overflow the displacements)"},
        BadInput{"no_k0",
                 "initial_stress:\n  gravity: {ground_level: 120.0, unit_weight: 26.0e3}\n",
                 "case.yaml:18: initial_stress.gravity.k0: required key 'k0' is missing"},
        BadInput{"zero_unit_weight",
                 "initial_stress:\n  gravity: {ground_level: 120.0, unit_weight: 0, k0: 1}\n",
                 "case.yaml:18: initial_stress.gravity.unit_weight: must be positive"},
        BadInput{"heavy",
                 "initial_stress:\n  gravity: {ground_level: 1, unit_weight: 2.0e9, k0: 1}\n",
                 "case.yaml:18: initial_stress.gravity.unit_weight: must be at most 1e+09 N/m^3 in "
                 "magnitude (no material is that heavy)"},
        BadInput{"negative_k0",
                 "initial_stress:\n  gravity: {ground_level: 1, unit_weight: 1.0e4, k0: -0.1}\n",
                 "case.yaml:18: initial_stress.gravity.k0: must be >= 0"},
        BadInput{"large_k0",
                 "initial_stress:\n  gravity: {ground_level: 1, unit_weight: 1.0e4, k0: 11}\n",
                 "case.yaml:18: initial_stress.gravity.k0: must be at most 10 (the ratio of "
                 "horizontal to vertical stress)"},
        BadInput{"far_ground",
                 "initial_stress:\n  gravity: {ground_level: 2.0e9, unit_weight: 1.0e4, k0: 1}\n",
                 "case.yaml:18: initial_stress.gravity.ground_level: must be at most 1e+09 m in "
                 "magnitude (the model's extent)"},
        BadInput{"yield_not_boolean", "initial_stress:\n  stress: [0, 0, 0]\n  allow_yield: 2\n",
                 "case.yaml:19: initial_stress.allow_yield: must be true or false, not '2'"},
        BadInput{"unknown_key", "initial_stress:\n  stres: [0, 0, 0]\n",
                 "case.yaml:18: initial_stress.stres: unknown key 'stres' (allowed here: stress, "
                 "gravity, allow_yield)"}),
    [](const auto& test) { return std::string(test.param.name); });

TEST(CaseReaderExcavation, ReadsEachKindOfBlockSelectorAndTheRelease) {
  const Case c = read_case_string(kSixBlockCase + R"(stages:
  - name: in situ
  - name: top heading
    excavate: {region: [[0.5, 1], [2.5, 1], [1.5, 2.5]]}
    release: 0.4
  - name: bench
    excavate: {box: [[0, 0], [1, 1]]}
  - name: lining
    install: {material: shotcrete}
  - name: props
    install: {blocks: [2, 0]}
)",
                                  "case.yaml");
  const std::vector<StageSpec>& st = c.spec.stages;
  ASSERT_EQ(st.size(), 5u);
  EXPECT_FALSE(st[0].excavate || st[0].install);
  EXPECT_EQ(st[0].release, 1.0);
  ASSERT_TRUE(st[1].excavate.has_value());
  EXPECT_EQ(st[1].excavate->kind, BlockSelector::Kind::region);
  EXPECT_EQ(st[1].excavate->region.vertices,
            (std::vector<Vec2>{{0.5, 1.0}, {2.5, 1.0}, {1.5, 2.5}}));
  EXPECT_EQ(st[1].excavate->source.line, 20);
  EXPECT_EQ(st[1].excavate->source.item, "stages[1].excavate.region");
  EXPECT_EQ(st[1].release, 0.4);
  EXPECT_EQ(st[2].excavate->kind, BlockSelector::Kind::box);
  EXPECT_EQ(st[2].excavate->box.lo, Vec2(0, 0));
  EXPECT_EQ(st[2].excavate->box.hi, Vec2(1, 1));
  EXPECT_EQ(st[2].release, 1.0);
  ASSERT_TRUE(st[3].install.has_value());
  EXPECT_EQ(st[3].install->kind, BlockSelector::Kind::material);
  EXPECT_EQ(st[3].install->material, "shotcrete");
  EXPECT_EQ(st[4].install->kind, BlockSelector::Kind::list);
  EXPECT_EQ(st[4].install->blocks, (std::vector<int>{2, 0}));  // as given; the model sorts
}

class BadStage : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadStage, IsNamedByFileLineAndItem) {
  EXPECT_EQ(read_error_of(kSixBlockCase + "stages:\n" + GetParam().text), GetParam().expected);
}

INSTANTIATE_TEST_SUITE_P(
    CaseReaderExcavation, BadStage,
    ::testing::Values(
        BadInput{"two_kinds", "  - name: s\n    excavate: {box: [[0, 0], [1, 1]], blocks: [0]}\n",
                 "case.yaml:19: stages[0].excavate: give only one of region, box, material or "
                 "blocks"},
        BadInput{"no_kind", "  - name: s\n    install: {}\n",
                 "case.yaml:19: stages[0].install: say which blocks: give one of region, box, "
                 "material or blocks"},
        BadInput{"unknown_key", "  - name: s\n    excavate: {regoin: [[0, 0], [1, 0], [0, 1]]}\n",
                 "case.yaml:19: stages[0].excavate.regoin: unknown key 'regoin' (allowed here: "
                 "region, box, material, blocks)"},
        BadInput{"two_point_region", "  - name: s\n    excavate: {region: [[0, 0], [1, 0]]}\n",
                 "case.yaml:19: stages[0].excavate.region: a region is a polygon [[x, y], ...] of "
                 "at least 3 points"},
        BadInput{"far_point", "  - name: s\n    excavate: {region: [[0, 0], [2.0e9, 0], [0, 1]]}\n",
                 "case.yaml:19: stages[0].excavate.region[1]: coordinates must lie within +-1e+09 "
                 "m, not [2e+09, 0]"},
        BadInput{"upside_down_box", "  - name: s\n    excavate: {box: [[1, 1], [0, 0]]}\n",
                 "case.yaml:19: stages[0].excavate.box: the first corner must be the lower-left "
                 "one: [[xmin, ymin], [xmax, ymax]]"},
        BadInput{"empty_material", "  - name: s\n    install: {material: ''}\n",
                 "case.yaml:19: stages[0].install.material: must not be empty"},
        BadInput{"negative_index", "  - name: s\n    install: {blocks: [2, -1]}\n",
                 "case.yaml:19: stages[0].install.blocks[1]: must be a block index: a whole number "
                 ">= 0 (blocks count from 0)"},
        BadInput{"fractional_index", "  - name: s\n    install: {blocks: [1.5]}\n",
                 "case.yaml:19: stages[0].install.blocks[0]: must be a whole number, not '1.5'"},
        BadInput{"repeated_index", "  - name: s\n    excavate: {blocks: [4, 1, 4]}\n",
                 "case.yaml:19: stages[0].excavate.blocks[2]: block 4 is listed twice"},
        BadInput{"no_index", "  - name: s\n    excavate: {blocks: []}\n",
                 "case.yaml:19: stages[0].excavate.blocks: list at least one block index"},
        BadInput{"zero_release", "  - name: s\n    excavate: {blocks: [4]}\n    release: 0\n",
                 "case.yaml:20: stages[0].release: must lie in (0, 1]: the fraction of the "
                 "excavation forces not yet released that this stage releases"},
        BadInput{"release_above_one",
                 "  - name: s\n    excavate: {blocks: [4]}\n    release: 1.5\n",
                 "case.yaml:20: stages[0].release: must lie in (0, 1]: the fraction of the "
                 "excavation forces not yet released that this stage releases"},
        BadInput{"release_not_a_number",
                 "  - name: s\n    excavate: {blocks: [4]}\n    release: .inf\n",
                 "case.yaml:20: stages[0].release: must be a finite number, not '.inf'"},
        BadInput{"release_before_any_excavation",
                 "  - name: s\n  - name: t\n    release: 0.5\n  - name: u\n"
                 "    excavate: {blocks: [4]}\n",
                 "case.yaml:20: stages[1].release: no stage up to this one excavates a block: "
                 "release applies to the forces of excavated blocks not yet released"}),
    [](const auto& test) { return std::string(test.param.name); });

// release is allowed on the excavating stage and on every later one, whether or not they
// excavate (it applies to the forces not yet released).
TEST(CaseReaderExcavation, AcceptsAReleaseFromTheFirstExcavationOn) {
  const Case c = read_case_string(kSixBlockCase + R"(stages:
  - name: in situ
  - name: excavate
    excavate: {blocks: [4]}
    release: 0.3
  - name: more
    release: 0.5
)",
                                  "case.yaml");
  EXPECT_EQ(c.spec.stages[1].release, 0.3);
  EXPECT_EQ(c.spec.stages[2].release, 0.5);
}

// The builder's checks come out with the reader's file, line and item.
TEST(CaseReaderExcavation, BuildResolvesTheSelectorsFromTheCaseFile) {
  const Model m = build_model(read_case_string(kSixBlockCase + R"(stages:
  - name: in situ
  - name: top heading
    excavate: {region: [[0.5, 1], [2.5, 1], [1.5, 2.5]]}
    release: 0.4
  - name: lining
    install: {material: shotcrete}
)",
                                               "case.yaml")
                                  .spec);
  ASSERT_EQ(m.stages.size(), 3u);
  EXPECT_EQ(m.stages[1].excavated, std::vector<int>{4});  // (1.5, 1.5) only is in the triangle
  EXPECT_EQ(m.stages[1].release, 0.4);
  EXPECT_EQ(m.stages[2].installed, std::vector<int>{5});
}

TEST(CaseReaderExcavation, BuildErrorsNameTheLineAndItem) {
  EXPECT_EQ(build_error_of(kSixBlockCase + R"(stages:
  - name: excavate
    excavate: {blocks: [4]}
  - name: again
    excavate: {box: [[1, 1], [2, 2]]}
)"),
            "case.yaml:21: stages[1].excavate.box: block 4 (centroid (1.5, 1.5)) is absent at this "
            "stage: excavated by stages[0] ('excavate')");
  EXPECT_EQ(build_error_of(kSixBlockCase + "stages:\n  - name: s\n    install: {blocks: [6]}\n"),
            "case.yaml:19: stages[0].install.blocks: there is no block 6: the model's 6 blocks "
            "are numbered from 0 to 5");
  EXPECT_EQ(
      build_error_of(kSixBlockCase + "stages:\n  - name: s\n    excavate: {material: granite}\n"),
      "case.yaml:19: stages[0].excavate.material: unknown material 'granite'");
  EXPECT_EQ(build_error_of(kSixBlockCase + "stages:\n  - name: s\n    excavate: "
                                           "{region: [[0, 0], [3, 2], [3, 0], [0, 2]]}\n"),
            "case.yaml:19: stages[0].excavate.region: the outline intersects itself: edges 1 and "
            "3 cross or touch");
}

}  // namespace
}  // namespace bimrock
