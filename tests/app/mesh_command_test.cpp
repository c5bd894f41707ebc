// `bimrock mesh` and the `domain` section of a case file, through the command line: blocks cut
// from a domain by joint sets, checked against hand counts and areas, each interface with the
// joint material of its set, bad geometry named with its line.
#include <cmath>

#include <gtest/gtest.h>

#include "support/results_folder.hpp"
#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

const std::string kMaterialsSupportsGravity = R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2, unit_weight: 25.0e3}
joint_materials:
  horizontal: {kn: 1.0e10, ks: 5.0e9}
  vertical: {kn: 2.0e10, ks: 5.0e9}
supports:
  - {line: [[0, 0], [6, 0]], type: fixed}
loads: {gravity: [0, -1]}
)";

// A 6 m x 4 m rectangle cut by horizontal joints every 1 m and vertical joints every 2 m.
const std::string kGrid = kMaterialsSupportsGravity + R"(domain:
  outline: [[0, 0], [6, 0], [6, 4], [0, 4]]
  material: rock
  joint_sets:
    - {material: horizontal, dip: 0, spacing: 1.0, origin: [0, 1]}
    - {material: vertical, dip: 90, spacing: 2.0, origin: [2, 0]}
)";

TEST(MeshCommand, TwoOrthogonalPersistentSetsCutTheExpectedGrid) {
  // A 6 m x 4 m rectangle, horizontal joints every 1 m and vertical joints every 2 m (offset so
  // that no joint runs along the outline): 4 rows x 3 columns = 12 blocks of 2 m^2, with
  // 3 x 3 = 9 horizontal interfaces and 4 x 2 = 8 vertical ones (counted by hand).
  const std::string text = kGrid;
  const testing::CommandResult r = testing::run_bimrock("mesh", text, "-o mesh");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = testing::read_json(r.folder / "mesh" / "summary.json");
  EXPECT_EQ(s.at("blocks").get<int>(), 12);
  EXPECT_NEAR(s.at("area_m2").get<double>(), 24.0, 1e-12 * 24.0);
  EXPECT_NEAR(s.at("smallest_block_m2").get<double>(), 2.0, 1e-12);
  EXPECT_NEAR(s.at("largest_block_m2").get<double>(), 2.0, 1e-12);
  EXPECT_EQ(s.at("interfaces_by_joint_material").at("horizontal").get<int>(), 9);
  EXPECT_EQ(s.at("interfaces_by_joint_material").at("vertical").get<int>(), 8);
  const nlohmann::json vtu = testing::read_vtu_with_meshio(r.folder / "mesh" / "blocks.vtu");
  EXPECT_EQ(vtu.at("cells").at("polygon").get<int>(), 12);
  std::filesystem::remove_all(r.folder);
}

TEST(MeshCommand, ATunnelIsCutOutAndTheRunConservesItsArea) {
  // A square hole of 1 m^2 in the middle: area 24 - 1. The cut around it (rock bridges and
  // convex partition) joins its pieces by continuum interfaces, and the case solves.
  const std::string text = kMaterialsSupportsGravity + R"(domain:
  outline: [[0, 0], [6, 0], [6, 4], [0, 4]]
  holes:
    - [[2.5, 1.5], [3.5, 1.5], [3.5, 2.5], [2.5, 2.5]]
  material: rock
  joint_sets:
    - {material: horizontal, dip: 0, spacing: 2.0, origin: [0, 1]}
)";
  const testing::CommandResult m = testing::run_bimrock("mesh", text, "-o mesh");
  ASSERT_EQ(m.exit_code, 0) << m.err;
  const nlohmann::json s = testing::read_json(m.folder / "mesh" / "summary.json");
  EXPECT_NEAR(s.at("area_m2").get<double>(), 23.0, 1e-12 * 23.0);
  EXPECT_GT(s.at("interfaces_by_joint_material").at("intact rock (continuum)").get<int>(), 0);
  const testing::CommandResult run = testing::run_bimrock("run", text, "-o results");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const nlohmann::json r = testing::read_json(run.folder / "results" / "summary.json");
  EXPECT_NEAR(r.at("model").at("area_m2").get<double>(), 23.0, 1e-12 * 23.0);
  std::filesystem::remove_all(m.folder);
  std::filesystem::remove_all(run.folder);
}

TEST(MeshCommand, BadGeometryIsNamedWithItsLine) {
  // The hole (line 13) reaches outside the outline.
  const std::string text = kMaterialsSupportsGravity + R"(domain:
  outline: [[0, 0], [6, 0], [6, 4], [0, 4]]
  holes:
    - [[5.5, 1], [7, 1], [7, 2], [5.5, 2]]
  material: rock
)";
  const testing::CommandResult r = testing::run_bimrock("mesh", text, "-o mesh");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("case.yaml:13: domain.holes[0]"), std::string::npos) << r.err;
  EXPECT_FALSE(std::filesystem::exists(r.folder / "mesh"));
  const testing::CommandResult spacing = testing::run_bimrock(
      "mesh",
      kMaterialsSupportsGravity +
          "domain:\n  outline: [[0, 0], [6, 0], [6, 4], [0, 4]]\n  material: rock\n"
          "  joint_sets:\n    - {material: horizontal, dip: 0, spacing: 0}\n",
      "-o mesh");
  EXPECT_EQ(spacing.exit_code, 2);
  EXPECT_NE(spacing.err.find("case.yaml:14: domain.joint_sets[0].spacing"), std::string::npos)
      << spacing.err;
  std::filesystem::remove_all(r.folder);
  std::filesystem::remove_all(spacing.folder);
}

// The mesh command keeps to limits.output_mb as a run does, before writing anything. The 12
// blocks of the grid above write a blocks.vtu of about 18 kB (48 vertices, 2 points for each of
// the 17 interfaces and 3 supports, 32 cells) beside the 1 MB allowed for the picture and the
// summary: just over 1 MB, within 1.1 MB.
TEST(MeshCommand, KeepsToTheOutputLimit) {
  const std::string grid = kGrid;
  const testing::CommandResult refused =
      testing::run_bimrock("mesh", grid + "limits: {output_mb: 1.0}\n", "-o mesh");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_EQ(refused.err.rfind("error: case.yaml:16: output: would generate about 1.02 MB of "
                              "blocks.vtu and pictures, more than limits.output_mb = 1",
                              0),
            0u)
      << refused.err;
  EXPECT_FALSE(std::filesystem::exists(refused.folder / "mesh"));
  const testing::CommandResult accepted =
      testing::run_bimrock("mesh", grid + "limits: {output_mb: 1.1}\n", "-o mesh");
  EXPECT_EQ(accepted.exit_code, 0) << accepted.err;
  EXPECT_TRUE(std::filesystem::exists(accepted.folder / "mesh" / "blocks.vtu"));
  std::filesystem::remove_all(refused.folder);
  std::filesystem::remove_all(accepted.folder);
}

}  // namespace
}  // namespace bimrock
