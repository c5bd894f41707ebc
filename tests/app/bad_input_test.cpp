// Bad input gets one clear message naming the file, line and item, a non-zero exit, and nothing
// written to the output folder. One test per kind of bad input, through the real command line.
#include <gtest/gtest.h>

#include "support/run_bimrock.hpp"
#include "support/two_blocks_case.hpp"

namespace bimrock {
namespace {

// A valid case: two blocks on a fixed base. Block 0 is on line 10, block 1 on line 11.
const std::string& kHeader = testing::kTwoBlocksHeader;
const std::string& kBlock0 = testing::kTwoBlocksBlock0;
const std::string& kBlock1 = testing::kTwoBlocksBlock1;

struct BadInput {
  const char* name;
  std::string text;
  std::string expected;  // must appear in the message: "case.yaml:<line>: <item>..."
};

class BadInputs : public ::testing::TestWithParam<BadInput> {};

TEST_P(BadInputs, StopWithOneClearMessageAndWriteNothing) {
  const testing::CommandResult r = testing::run_bimrock("run", GetParam().text, "-o results");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message: " << r.err;
  EXPECT_FALSE(std::filesystem::exists(r.folder / "results"));
  // No temporary folder left behind either.
  for (const auto& entry : std::filesystem::directory_iterator(r.folder))
    EXPECT_TRUE(entry.is_regular_file()) << entry.path();
  std::filesystem::remove_all(r.folder);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, BadInputs,
    ::testing::Values(
        BadInput{"MalformedYaml", "schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2\n",
                 "case.yaml:"},
        BadInput{"UnknownKey",
                 kHeader + kBlock0 + "  - {material: rock, vertixes: [[1, 0], [2, 0], [2, 1]]}\n",
                 "case.yaml:11:"},
        BadInput{"MissingMaterial",
                 kHeader + kBlock0 +
                     "  - {material: granit, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}\n",
                 "case.yaml:11: blocks[1]: unknown material 'granit'"},
        BadInput{"ClockwisePolygon",
                 kHeader + kBlock0 +
                     "  - {material: rock, vertices: [[1, 0], [1, 1], [2, 1], [2, 0]]}\n",
                 "case.yaml:11: blocks[1]: the vertices are clockwise"},
        BadInput{
            "NonConvexPolygon",
            kHeader + kBlock0 +
                "  - {material: rock, vertices: [[1, 0], [2, 0], [1.5, 0.5], [2, 1], [1, 1]]}\n",
            "case.yaml:11: blocks[1]: vertex 3 makes the polygon non-convex"},
        BadInput{"DuplicateVertex",
                 kHeader + kBlock0 +
                     "  - {material: rock, vertices: [[1, 0], [2, 0], [2, 0], [2, 1], [1, 1]]}\n",
                 "case.yaml:11: blocks[1]: vertex 3 duplicates an earlier vertex"},
        BadInput{"ZeroArea",
                 kHeader + kBlock0 + "  - {material: rock, vertices: [[1, 0], [1.5, 0], [2, 0]]}\n",
                 "case.yaml:11: blocks[1]: the polygon has zero area"},
        BadInput{"OverlappingBlocks",
                 kHeader + kBlock0 +
                     "  - {material: rock, vertices: [[0.5, 0], [2, 0], [2, 1], [0.5, 1]]}\n",
                 "case.yaml:11: blocks[1]: overlaps blocks[0] (line 10)"},
        BadInput{"NaNStiffness",
                 "schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2}\njoint_materials:\n  joint: "
                 "{kn: .nan, ks: 1.0e10}\n",
                 "case.yaml:5:"},
        BadInput{"NegativeStiffness",
                 "schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2}\njoint_materials:\n  joint: "
                 "{kn: -1.0e10, ks: 1.0e10}\njoints: {default: joint}\nsupports:\n  - {line: [[0, "
                 "0], [2, 0]], type: fixed}\nblocks:\n" +
                     kBlock0 + kBlock1,
                 "case.yaml:5: joint_materials.joint"},
        BadInput{"UnsupportedStructure",
                 "schema: 1\nmaterials:\n  rock: {E: 10.0e9, nu: 0.2}\njoint_materials:\n  joint: "
                 "{kn: 1.0e10, ks: 1.0e10}\njoints: {default: joint}\nblocks:\n" +
                     kBlock0 + kBlock1,
                 "case.yaml: the structure is not fully supported: blocks[0] (line 8) and "
                 "blocks[1] (line 9)"}),
    [](const auto& p) { return std::string(p.param.name); });

TEST(BadInputs, AnUnreadableFileIsNamed) {
  const testing::CommandResult r = testing::run_bimrock("run", "", "-o results");
  std::filesystem::remove(r.folder / "case.yaml");
  const std::string cmd =
      "cd '" + r.folder.string() + "' && '" + BIMROCK_BINARY + "' run missing.yaml 2> stderr.txt";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  EXPECT_NE(testing::read_text(r.folder / "stderr.txt").find("missing.yaml"), std::string::npos);
  std::filesystem::remove_all(r.folder);
}

TEST(BadInputs, AFailedRunLeavesEarlierResultsUntouched) {
  const testing::CommandResult ok =
      testing::run_bimrock("run", kHeader + kBlock0 + kBlock1, "-o results");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const std::string before = testing::read_text(ok.folder / "results" / "summary.json");
  std::ofstream(ok.folder / "case.yaml") << kHeader + kBlock0;  // block 1 gone: still valid
  std::ofstream(ok.folder / "case.yaml", std::ios::app)
      << "  - {material: granit, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}\n";
  const std::string cmd = "cd '" + ok.folder.string() + "' && '" + BIMROCK_BINARY +
                          "' run case.yaml -o results 2> /dev/null";
  EXPECT_NE(std::system(cmd.c_str()), 0);
  EXPECT_EQ(testing::read_text(ok.folder / "results" / "summary.json"), before);
  std::filesystem::remove_all(ok.folder);
}

}  // namespace
}  // namespace bimrock
