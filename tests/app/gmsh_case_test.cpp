// A case file's `mesh` section, through the command line: the cells of a gmsh mesh
// (tests/data/gmsh/slope.geo, meshed by gmsh) become blocks, their physical groups materials,
// supports, loads and a joint; counts compared with meshio's reading of the same file
// (tests/support/read_msh.py) and areas with the closed form of the outline. Every bad mesh
// stops with one message naming the file, the line and the item, and writes nothing.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include <gtest/gtest.h>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/model.hpp>

#include "support/results_folder.hpp"
#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

std::string data(const std::string& name) {
  return std::string(BIMROCK_SOURCE_DIR) + "/tests/data/gmsh/" + name;
}

/// meshio's counts for a .msh file: cells by type, area, internal and boundary edges, line
/// elements by physical curve.
nlohmann::json read_with_meshio(const std::string& file) {
  const std::string cmd = std::string(BIMROCK_PYTHON) + " '" + BIMROCK_SOURCE_DIR +
                          "/tests/support/read_msh.py' '" + file + "'";
  std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(cmd.c_str(), "r"), pclose);
  std::string text;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe.get())) > 0;)
    text.append(buffer, n);
  return nlohmann::json::parse(text);
}

const std::string kMeshMaterials = R"(schema: 1
materials:
  granite: {E: 50.0e9, nu: 0.25, unit_weight: 26.0e3}
  clay: {E: 1.0e9, nu: 0.3, unit_weight: 20.0e3}
joint_materials:
  fault: {kn: 1.0e10, ks: 1.0e9}
)";

/// The slope of tests/data/gmsh/slope.geo on a fixed base and rollers, under gravity; the fault
/// (a physical curve inside the soil) gets its joint material by a rule.
std::string slope_case(const std::string& mesh_file) {
  return kMeshMaterials + "mesh:\n  file: " + mesh_file + R"(
  materials: {rock: granite, soil: clay}
joints:
  rules:
    - {material: fault, group: fault}
supports:
  - {group: base}
  - {group: left, type: roller}
  - {group: right, type: roller}
loads: {gravity: [0, -1]}
)";
}

TEST(GmshCase, EveryCellBecomesOneConvexCounterClockwiseBlock) {
  const nlohmann::json ref = read_with_meshio(data("slope.msh"));
  const int cells =
      ref.at("cells").at("triangle").get<int>() + ref.at("cells").at("quad").get<int>();
  const testing::CommandResult r =
      testing::run_bimrock("mesh", slope_case(data("slope.msh")), "-o mesh");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = testing::read_json(r.folder / "mesh" / "summary.json");
  EXPECT_EQ(s.at("blocks").get<int>(), cells);
  EXPECT_EQ(s.at("blocks_by_material").at("granite").get<int>(),
            ref.at("cells").at("quad").get<int>());  // slope.geo: quadrangles in the rock only
  // Outline (0,0) (40,0) (40,20) (25,20) (15,10) (0,10): 40 x 10 + 10 x 10 / 2 + 15 x 10 m^2.
  EXPECT_NEAR(s.at("area_m2").get<double>(), 600.0, 1e-12 * 600.0);
  // One interface per edge shared by two cells; the fault's, one per line element of it.
  EXPECT_EQ(s.at("interfaces").get<int>(), ref.at("internal_edges").get<int>());
  const int fault = ref.at("lines_by_group").at("fault").get<int>();
  EXPECT_EQ(s.at("interfaces_by_joint_material").at("fault").get<int>(), fault);
  EXPECT_EQ(s.at("interfaces_by_joint_material").at("intact rock (continuum)").get<int>(),
            ref.at("internal_edges").get<int>() - fault);
  const nlohmann::json& lines = ref.at("lines_by_group");
  EXPECT_EQ(
      s.at("support_interfaces").get<int>(),
      lines.at("base").get<int>() + lines.at("left").get<int>() + lines.at("right").get<int>());
  const nlohmann::json vtu = testing::read_vtu_with_meshio(r.folder / "mesh" / "blocks.vtu");
  EXPECT_EQ(vtu.at("cells").at("polygon").get<int>(), cells);

  // The blocks themselves: one per cell, convex and counter-clockwise at zero tolerance.
  const Model model = build_model(read_case_file((r.folder / "case.yaml").string()).spec);
  ASSERT_EQ(model.n_blocks(), cells);
  for (const Block& b : model.blocks) {
    EXPECT_EQ(check_convex_polygon(b.polygon, 0.0).defect, PolygonDefect::none) << b.source.item;
    EXPECT_GT(b.area, 0.0) << b.source.item;
  }
  std::filesystem::remove_all(r.folder);
}

TEST(GmshCase, RunsUnderGravity) {
  const testing::CommandResult r =
      testing::run_bimrock("run", slope_case(data("slope.msh")), "-o results");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json s = testing::read_json(r.folder / "results" / "summary.json");
  EXPECT_NEAR(s.at("model").at("area_m2").get<double>(), 600.0, 1e-12 * 600.0);
  std::filesystem::remove_all(r.folder);
}

TEST(GmshCase, TheMeshFileIsFoundBesideTheCaseFile) {
  const std::filesystem::path folder = testing::fresh_folder("bimrock-gmsh");
  std::filesystem::create_directories(folder / "slope");
  std::filesystem::copy_file(data("slope.msh"), folder / "slope" / "slope.msh");
  std::ofstream(folder / "slope" / "case.yaml") << slope_case("slope.msh");
  const std::string cmd = "cd '" + folder.string() + "' && '" + BIMROCK_BINARY +
                          "' mesh slope/case.yaml -o out > /dev/null 2> stderr.txt";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << testing::read_text(folder / "stderr.txt");
  EXPECT_TRUE(std::filesystem::exists(folder / "out" / "summary.json"));
  std::filesystem::remove_all(folder);
}

struct BadMeshCase {
  const char* name;
  std::string text;
  std::string expected;  // must appear in the message
};

class GmshBadInputs : public ::testing::TestWithParam<BadMeshCase> {};

TEST_P(GmshBadInputs, StopWithOneClearMessageAndWriteNothing) {
  const testing::CommandResult r = testing::run_bimrock("run", GetParam().text, "-o results");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(GetParam().expected), std::string::npos) << r.err;
  EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << "one message: " << r.err;
  EXPECT_FALSE(std::filesystem::exists(r.folder / "results"));
  for (const auto& entry : std::filesystem::directory_iterator(r.folder))
    EXPECT_TRUE(entry.is_regular_file()) << entry.path();
  std::filesystem::remove_all(r.folder);
}

/// A case on the one-surface meshes ("rock", with the physical curve "base"); mesh on line 7.
std::string square_case(const std::string& file) {
  return kMeshMaterials + "mesh:\n  file: " + data(file) +
         "\n  materials: {rock: granite}\nsupports:\n  - {group: base}\n";
}

INSTANTIATE_TEST_SUITE_P(
    Cases, GmshBadInputs,
    ::testing::Values(
        BadMeshCase{"InvertedCell", square_case("inverted_cell.msh"),
                    "inverted_cell.msh:38: element 4 (surface 1): an inverted cell"},
        BadMeshCase{"ClockwiseSurface", square_case("clockwise_surface.msh"),
                    "clockwise_surface.msh:63: element 3 (surface 1): every cell of surface 1 is "
                    "clockwise"},
        BadMeshCase{"DegenerateCell", square_case("repeated_node.msh"),
                    "repeated_node.msh:37: element 3 (surface 1): a degenerate cell"},
        BadMeshCase{"ZeroAreaCell", square_case("zero_area_cell.msh"),
                    "zero_area_cell.msh:37: element 3 (surface 1): a degenerate cell: zero area"},
        BadMeshCase{"NonConvexQuadrangle", square_case("non_convex_quad.msh"),
                    "non_convex_quad.msh:36: element 2 (surface 1): a non-convex quadrangle"},
        BadMeshCase{"UnsupportedElementType", square_case("second_order.msh"),
                    "second_order.msh:38: element 2 (surface 1): element type 9 (6-node "
                    "second-order triangle) is not supported"},
        BadMeshCase{"Version22", square_case("version22.msh"),
                    "version22.msh:2: $MeshFormat: MSH version 2.2 is not supported"},
        BadMeshCase{"CellsWithoutGroup", square_case("no_groups.msh"),
                    "no_groups.msh:31: element 2 (surface 1): belongs to no physical surface"},
        BadMeshCase{"UnmappedGroup",
                    kMeshMaterials + "mesh:\n  file: " + data("slope.msh") +
                        "\n  materials: {rock: granite}\n",
                    "case.yaml:9: mesh.materials: no material for physical surface 'soil'"},
        BadMeshCase{"UnknownGroupInMaterials",
                    kMeshMaterials + "mesh:\n  file: " + data("slope.msh") +
                        "\n  materials: {rock: granite, sand: clay}\n",
                    "case.yaml:9: mesh.materials.sand: 'sand' is not a physical surface of "},
        BadMeshCase{"UnknownGroupInSelector",
                    kMeshMaterials + "mesh:\n  file: " + data("slope.msh") +
                        "\n  materials: {rock: granite, soil: clay}\nsupports:\n"
                        "  - {group: bottom}\n",
                    "case.yaml:11: supports[0].group: unknown group 'bottom': not a physical "
                    "curve of " +
                        data("slope.msh") +
                        " (its physical curves: 'base', 'fault', 'left', 'right', 'slope_face')"},
        BadMeshCase{"SurfaceGroupInSelector",
                    kMeshMaterials + "mesh:\n  file: " + data("slope.msh") +
                        "\n  materials: {rock: granite, soil: clay}\nloads:\n  tractions:\n"
                        "    - {group: soil, normal: -1.0e6}\n",
                    "case.yaml:12: loads.tractions[0].group: 'soil' is a physical surface"},
        BadMeshCase{"UnknownMaterial",
                    kMeshMaterials + "mesh:\n  file: " + data("fan.msh") +
                        "\n  materials: {rock: granit}\n",
                    "case.yaml:9: mesh.materials.rock: unknown material 'granit'"},
        BadMeshCase{"GroupWithoutMesh",
                    kMeshMaterials +
                        "blocks:\n  - {material: granite, vertices: [[0, 0], [1, 0], [1, 1]]}\n"
                        "supports:\n  - {group: base}\n",
                    "case.yaml:10: supports[0].group: a group selects the line elements of a "
                    "mesh's physical curve"},
        BadMeshCase{"MeshAndBlocks",
                    kMeshMaterials +
                        "blocks:\n  - {material: granite, vertices: [[0, 0], [1, 0], [1, "
                        "1]]}\nmesh:\n  file: " +
                        data("fan.msh") + "\n  materials: {rock: granite}\n",
                    "case.yaml:9: mesh: give one of blocks, a domain or a mesh, not several"},
        BadMeshCase{"UnknownKey",
                    kMeshMaterials + "mesh:\n  file: " + data("fan.msh") +
                        "\n  materials: {rock: granite}\n  interface: continuum\n",
                    "case.yaml:10: mesh.interface: unknown key 'interface'"},
        BadMeshCase{"MissingFile", square_case("no_such.msh"),
                    "case.yaml:8: mesh.file: cannot open the mesh file "}),
    [](const auto& p) { return std::string(p.param.name); });

}  // namespace
}  // namespace bimrock
