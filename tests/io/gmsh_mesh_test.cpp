// The gmsh MSH 4.1 reader: cells, line elements and physical groups of hand-written meshes and of
// one made by gmsh (tests/data/gmsh/slope.geo), compared with counts and areas that come from
// elsewhere: closed-form areas of the outlines and meshio (an independent reader, through
// tests/support/read_msh.py); and every kind of mesh it must refuse, named with file, line and
// item.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <bimrock/io/gmsh_mesh.hpp>
#include <bimrock/model/errors.hpp>

namespace bimrock {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

std::string data(const std::string& name) {
  return std::string(BIMROCK_SOURCE_DIR) + "/tests/data/gmsh/" + name;
}

/// meshio's counts for a .msh file (tests/support/read_msh.py).
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

double total_area(const GmshMesh& mesh) {
  double a = 0.0;
  for (const MeshCell& c : mesh.cells)
    a += signed_area(c.polygon);
  return a;
}

/// The message of the InputError that reading `file` throws ("" if none).
std::string error_reading(const std::string& file) {
  try {
    read_gmsh_mesh(file);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string error_parsing(const std::string& text) {
  try {
    parse_gmsh_mesh(text, "m.msh");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(GmshMesh, ReadsTrianglesLinesAndTheirPhysicalGroups) {
  const GmshMesh mesh = read_gmsh_mesh(data("fan.msh"));
  ASSERT_EQ(mesh.cells.size(), 4u);  // the file: 4 triangles round the centre of a unit square
  EXPECT_NEAR(total_area(mesh), 1.0, 1e-12);  // the unit square
  for (const MeshCell& c : mesh.cells) {
    EXPECT_EQ(c.surface, 1);
    EXPECT_THAT(c.groups, ElementsAre("rock"));
    EXPECT_NEAR(signed_area(c.polygon), 0.25, 1e-15);  // a quarter of the square each
  }
  EXPECT_EQ(mesh.cells[0].tag, 2);
  EXPECT_EQ(mesh.cells[0].line, 36);
  EXPECT_THAT(mesh.cells[0].nodes, ElementsAre(1, 2, 5));
  ASSERT_EQ(mesh.lines.size(), 1u);
  EXPECT_THAT(mesh.lines[0].groups, ElementsAre("base"));
  EXPECT_EQ(mesh.lines[0].segment.b, Vec2(1, 0));
  EXPECT_THAT(mesh.group_names(2), ElementsAre("rock"));
  EXPECT_THAT(mesh.group_names(1), ElementsAre("base"));
}

TEST(GmshMesh, AMeshMadeByGmshMatchesMeshioAndTheOutlinesArea) {
  // tests/data/gmsh/slope.geo: outline (0,0) (40,0) (40,20) (25,20) (15,10) (0,10), area
  // 40 x 10 + 10 x 10 / 2 + 15 x 10 = 600 m^2; quadrangles below y = 5, triangles above.
  const GmshMesh mesh = read_gmsh_mesh(data("slope.msh"));
  const nlohmann::json ref = read_with_meshio(data("slope.msh"));
  int triangles = 0, quads = 0;
  for (const MeshCell& c : mesh.cells) {
    (c.nodes.size() == 3 ? triangles : quads) += 1;
    EXPECT_EQ(check_convex_polygon(c.polygon, 0.0).defect, PolygonDefect::none) << c.tag;
    EXPECT_THAT(c.groups, ElementsAre(c.surface == 1 ? "rock" : "soil")) << c.tag;
  }
  EXPECT_EQ(triangles, ref.at("cells").at("triangle").get<int>());
  EXPECT_EQ(quads, ref.at("cells").at("quad").get<int>());
  EXPECT_NEAR(total_area(mesh), 600.0, 1e-12 * 600.0);
  EXPECT_EQ(mesh.lines.size(), ref.at("cells").at("line").get<std::size_t>());
  for (const auto& [group, n] : ref.at("lines_by_group").items()) {
    int count = 0;
    for (const MeshLine& l : mesh.lines)
      count += static_cast<int>(std::count(l.groups.begin(), l.groups.end(), group));
    EXPECT_EQ(count, n.get<int>()) << group;
  }
  EXPECT_THAT(mesh.group_names(1), ElementsAre("base", "fault", "left", "right", "slope_face"));
  EXPECT_THAT(mesh.group_names(2), ElementsAre("rock", "soil"));
}

struct BadMesh {
  const char* name;
  const char* file;
  std::string expected;  // must appear in the message
};

class BadMeshes : public ::testing::TestWithParam<BadMesh> {};

TEST_P(BadMeshes, AreRefusedNamingFileLineAndItem) {
  const std::string message = error_reading(data(GetParam().file));
  EXPECT_THAT(message, HasSubstr(std::string(GetParam().file) + ":"));
  EXPECT_THAT(message, HasSubstr(GetParam().expected));
}

// The line numbers are those of the offending element, node or header in each file.
INSTANTIATE_TEST_SUITE_P(
    Files, BadMeshes,
    ::testing::Values(
        BadMesh{"InvertedCell", "inverted_cell.msh",
                "inverted_cell.msh:38: element 4 (surface 1): an inverted cell: clockwise, while "
                "3 other cells of surface 1 are counter-clockwise"},
        BadMesh{"WholeSurfaceClockwise", "clockwise_surface.msh",
                "clockwise_surface.msh:63: element 3 (surface 1): every cell of surface 1 is "
                "clockwise (inverted)"},
        BadMesh{"WholeSurfaceClockwiseSaysHowToFixIt", "clockwise_surface.msh",
                "add `ReverseMesh Surface{1};` to the .geo"},
        BadMesh{"RepeatedNode", "repeated_node.msh",
                "repeated_node.msh:37: element 3 (surface 1): a degenerate cell: node 3 is "
                "repeated"},
        BadMesh{"ZeroAreaCell", "zero_area_cell.msh",
                "zero_area_cell.msh:37: element 3 (surface 1): a degenerate cell: zero area"},
        BadMesh{"NonConvexQuadrangle", "non_convex_quad.msh",
                "non_convex_quad.msh:36: element 2 (surface 1): a non-convex quadrangle (reflex "
                "corner at node 5)"},
        BadMesh{"SecondOrderTriangle", "second_order.msh",
                "second_order.msh:38: element 2 (surface 1): element type 9 (6-node "
                "second-order triangle) is not supported"},
        BadMesh{"NodeOffThePlane", "off_plane.msh",
                "off_plane.msh:29: node 5: z = 0.5: bimrock reads plane meshes"},
        BadMesh{"Version22", "version22.msh",
                "version22.msh:2: $MeshFormat: MSH version 2.2 is not supported: bimrock reads "
                "MSH 4.1 ASCII"},
        BadMesh{"Binary", "binary.msh",
                "binary.msh:2: $MeshFormat: a binary MSH file: bimrock reads ASCII files"}),
    [](const auto& p) { return std::string(p.param.name); });

TEST(GmshMesh, AMissingFileIsNamed) {
  EXPECT_THAT(error_reading(data("no_such.msh")),
              HasSubstr("no_such.msh: cannot open the mesh file: no such file"));
}

// A minimal valid file, to be broken by each of the tests below: one triangle and one line.
const std::string kHead = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
const std::string kNames = "$PhysicalNames\n2\n1 7 \"the base\"\n2 3 \"rock\"\n$EndPhysicalNames\n";
const std::string kEntities =
    "$Entities\n0 1 1 0\n1 0 0 0 1 0 0 1 7 0\n1 0 0 0 1 1 0 1 3 0\n$EndEntities\n";
const std::string kNodes = "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n";
const std::string kElements =
    "$Elements\n2 2 1 2\n1 1 1 1\n1 1 2\n2 1 2 1\n2 1 2 3\n$EndElements\n";

TEST(GmshMesh, NamesWithSpacesUnknownSectionsAndWindowsLineEndsAreRead) {
  std::string text = kHead + kNames + "$NodeData\n1\n\"p\"\n$EndNodeData\n" + kEntities + kNodes +
                     kElements + "$Periodic\n0\n$EndPeriodic\n";
  std::string crlf;
  for (const char c : text)
    crlf += c == '\n' ? std::string("\r\n") : std::string(1, c);
  const GmshMesh mesh = parse_gmsh_mesh(crlf, "m.msh");
  ASSERT_EQ(mesh.cells.size(), 1u);
  ASSERT_EQ(mesh.lines.size(), 1u);
  EXPECT_THAT(mesh.lines[0].groups, ElementsAre("the base"));
  EXPECT_NEAR(signed_area(mesh.cells[0].polygon), 0.5, 1e-15);
}

TEST(GmshMesh, AnUnnamedGroupIsCalledByItsTag) {
  const GmshMesh mesh = parse_gmsh_mesh(kHead + kEntities + kNodes + kElements, "m.msh");
  EXPECT_THAT(mesh.cells[0].groups, ElementsAre("3"));
  EXPECT_THAT(mesh.group_names(1), ElementsAre("7"));
}

TEST(GmshMesh, ParametricCoordinatesAfterXYZAreIgnored) {
  const std::string nodes =
      "$Nodes\n1 3 1 3\n2 1 1 3\n1\n2\n3\n0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n$EndNodes\n";
  EXPECT_EQ(parse_gmsh_mesh(kHead + kEntities + nodes + kElements, "m.msh").cells.size(), 1u);
}

TEST(GmshMesh, MalformedFilesAreNamedWithTheirLine) {
  // Lines: 1-3 $MeshFormat, 4-8 $Entities, 9-18 $Nodes (coordinates on 15-17), 19- $Elements.
  EXPECT_THAT(error_parsing(kHead + kEntities +
                            "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 x 0\n0 1 0\n$EndNodes\n" +
                            kElements),
              HasSubstr("m.msh:16: node 2: expected y (a number), found 'x'"));
  EXPECT_THAT(error_parsing(kHead + kEntities + kNodes +
                            "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 9\n$EndElements\n"),
              HasSubstr("m.msh:22: element 1: refers to node 9, which $Nodes does not define"));
  EXPECT_THAT(error_parsing(kHead + kEntities + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n"),
              HasSubstr("m.msh:13: $Nodes: the file ends inside the section"));
  EXPECT_THAT(error_parsing(kHead + kEntities + kNodes +
                            "$Elements\n1 1 1 1\n3 1 4 1\n1 1 2 3 3\n$EndElements\n"),
              HasSubstr("m.msh:22: element 1: a 3D element (type 4 (4-node tetrahedron))"));
  EXPECT_THAT(error_parsing(kHead + kEntities + kNodes +
                            "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3\n$EndElements\n"),
              HasSubstr("m.msh:22: element 1 (surface 1): expected the element tag and its node "
                        "tags for its type (5 values), found 4"));
  EXPECT_THAT(error_parsing(kHead + "$PartitionedEntities\n"),
              HasSubstr("m.msh:4: $PartitionedEntities: a partitioned mesh"));
  EXPECT_THAT(error_parsing(kHead + kEntities + kNodes), HasSubstr("$Elements: missing"));
  EXPECT_THAT(error_parsing("hello\n"), HasSubstr("m.msh:1: not a gmsh mesh"));
  EXPECT_THAT(error_parsing(kHead + "$Comments\nnever closed\n"),
              HasSubstr("m.msh:4: $Comments: the section is not closed by '$EndComments'"));
}

// Node coordinates are bounded as a case file's points are (+-1e9 m): beyond, exact geometry
// overflows. 1e9 itself is accepted, the next power of ten (a mesh drawn in mm of a 1e6 m
// region, say) is refused with the node's line and tag.
TEST(GmshMesh, NodeCoordinatesAreBoundedLikeACaseFilesPoints) {
  const auto nodes = [](const std::string& second, const std::string& third) {
    return "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n" + second + "\n" + third + "\n$EndNodes\n";
  };
  const GmshMesh big =
      parse_gmsh_mesh(kHead + kEntities + nodes("1e9 -1e9 0", "0 1e9 0") + kElements, "m.msh");
  ASSERT_EQ(big.cells.size(), 1u);
  EXPECT_EQ(big.cells[0].polygon.vertices[1], Vec2(1e9, -1e9));
  EXPECT_THAT(error_parsing(kHead + kEntities + nodes("1e10 0 0", "0 1 0") + kElements),
              HasSubstr("m.msh:16: node 2: coordinates must lie within +-1e+09 m, not [1e+10, 0]"));
  EXPECT_THAT(
      error_parsing(kHead + kEntities + nodes("1 0 0", "0 -1.0e308 0") + kElements),
      HasSubstr("m.msh:17: node 3: coordinates must lie within +-1e+09 m, not [0, -1e+308]"));
}

}  // namespace
}  // namespace bimrock
