// The gmsh mesh from the sections of its MSH 4.1 file (msh_sections.hpp, read line by line with
// msh_lines.hpp so that every error has its line): the nodes on the plane, the elements'
// nodes defined, the cells checked as blocks, the physical groups named.
#include <bimrock/io/gmsh_mesh.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <unordered_set>

#include <bimrock/io/msh_sections.hpp>
#include <bimrock/model/errors.hpp>

namespace bimrock {
namespace {

using msh::Cursor;
using msh::Node;
using msh::Parsed;
using msh::RawElement;
using msh::read_sections;

/// A number as a person writes it: 0.5, 1e-08 (std::to_string would give 0.500000, 0.000000).
std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

std::string describe_item(const MeshCell& c) {
  return "element " + std::to_string(c.tag) + " (surface " + std::to_string(c.surface) + ")";
}

[[noreturn]] void fail_cell(const GmshMesh& mesh, const MeshCell& c, const std::string& message) {
  throw InputError(mesh.file, c.line, describe_item(c), message);
}

/// Cells must be blocks: distinct nodes, non-zero area, counter-clockwise, convex. A surface
/// whose cells are all clockwise was meshed with its normal along -z: say how to fix that.
void check_cells(const GmshMesh& mesh, double tol) {
  std::map<int, std::pair<int, int>> turns;  // surface -> (counter-clockwise, clockwise) cells
  for (const MeshCell& c : mesh.cells) {
    const double area = signed_area(c.polygon);
    auto& [ccw, cw] = turns[c.surface];
    (area > 0.0 ? ccw : cw) += 1;
  }
  for (const MeshCell& c : mesh.cells) {
    const std::size_t n = c.nodes.size();
    for (std::size_t i = 0; i < n; ++i) {
      for (std::size_t j = i + 1; j < n; ++j) {
        if (c.nodes[i] == c.nodes[j])
          fail_cell(mesh, c,
                    "a degenerate cell: node " + std::to_string(c.nodes[i]) + " is repeated");
        if ((c.polygon.vertices[i] - c.polygon.vertices[j]).norm() <= tol) {
          fail_cell(mesh, c,
                    "a degenerate cell: nodes " + std::to_string(c.nodes[i]) + " and " +
                        std::to_string(c.nodes[j]) +
                        " coincide (closer than the model's tolerance, " + number(tol) + " m)");
        }
      }
    }
    const PolygonCheck check = check_convex_polygon(c.polygon, tol);
    switch (check.defect) {
      case PolygonDefect::none:
        break;
      case PolygonDefect::zero_area:
        fail_cell(
            mesh, c,
            "a degenerate cell: zero area (its nodes lie on one line, to the model's tolerance)");
      case PolygonDefect::clockwise: {
        const int ccw = turns.at(c.surface).first;
        if (ccw == 0) {
          const std::string s = std::to_string(c.surface);
          fail_cell(
              mesh, c,
              "every cell of surface " + s +
                  " is clockwise (inverted): the surface was meshed with its normal along -z, "
                  "e.g. from a clockwise curve loop. In gmsh, add `ReverseMesh Surface{" +
                  s + "};` to the .geo, or list the curve loop of surface " + s +
                  " counter-clockwise, and mesh again");
        }
        fail_cell(mesh, c,
                  "an inverted cell: clockwise, while " + std::to_string(ccw) +
                      " other cells of surface " + std::to_string(c.surface) +
                      " are counter-clockwise (a tangled mesh: mesh the surface again)");
      }
      case PolygonDefect::non_convex:
        fail_cell(mesh, c,
                  "a non-convex quadrangle (reflex corner at node " +
                      std::to_string(c.nodes[check.vertex]) +
                      "): a block must be convex; mesh again (e.g. another "
                      "`Mesh.RecombinationAlgorithm`, "
                      "or triangles)");
      default:
        fail_cell(mesh, c, describe(check));
    }
  }
}

/// The names of the physical groups of entity (dim, tag).
std::vector<std::string> groups_of(const Parsed& p, int dim, int tag) {
  std::vector<std::string> names;
  const auto it = p.entity_groups.find({dim, tag});
  if (it == p.entity_groups.end())
    return names;
  for (const int g : it->second) {
    const auto name = p.names.find({dim, g});
    names.push_back(name == p.names.end() ? std::to_string(g) : name->second);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

GmshMesh assemble(const Parsed& p, const std::string& file) {
  GmshMesh mesh;
  mesh.file = file;

  // Nodes off the plane: the tolerance is the model's (1e-9 of the size of the mesh).
  BBox box;
  for (const auto& [tag, node] : p.nodes)
    box.add(node.xy);
  const double tol = model_tolerance(box);
  const Node* off_plane = nullptr;
  std::int64_t off_tag = 0;
  for (const auto& [tag, node] : p.nodes) {
    // The first in the file, not in the hash map's order, so that the message is reproducible.
    if (std::abs(node.z) > tol && (!off_plane || node.line < off_plane->line)) {
      off_plane = &node;
      off_tag = tag;
    }
  }
  if (off_plane) {
    throw InputError(
        file, off_plane->line, "node " + std::to_string(off_tag),
        "z = " + number(off_plane->z) + ": bimrock reads plane meshes in the x-y plane (z = 0)");
  }

  std::unordered_set<std::int64_t> tags;
  for (const RawElement& e : p.elements) {
    const std::string item = "element " + std::to_string(e.tag);
    if (!tags.insert(e.tag).second)
      throw InputError(file, e.line, item, "the element tag is used twice");
    std::vector<Vec2> xy;
    for (const std::int64_t n : e.nodes) {
      const auto it = p.nodes.find(n);
      if (it == p.nodes.end())
        throw InputError(file, e.line, item,
                         "refers to node " + std::to_string(n) + ", which $Nodes does not define");
      xy.push_back(it->second.xy);
    }
    if (e.dim == 2) {
      mesh.cells.push_back(
          {e.tag, e.entity, e.nodes, Polygon{xy}, groups_of(p, 2, e.entity), e.line});
    } else {
      mesh.lines.push_back({e.tag,
                            e.entity,
                            {e.nodes[0], e.nodes[1]},
                            Segment{xy[0], xy[1]},
                            groups_of(p, 1, e.entity),
                            e.line});
    }
  }

  BBox cells_box;
  for (const MeshCell& c : mesh.cells)
    cells_box.add(bbox_of(c.polygon));
  check_cells(mesh, model_tolerance(cells_box));

  // Every named group, and every unnamed one an entity uses.
  std::set<std::pair<int, int>> seen;
  for (const auto& [key, name] : p.names) {
    if (seen.insert(key).second)
      mesh.groups.push_back({key.first, key.second, name});
  }
  for (const auto& [entity, groups] : p.entity_groups) {
    for (const int g : groups) {
      if (seen.insert({entity.first, g}).second)
        mesh.groups.push_back({entity.first, g, std::to_string(g)});
    }
  }
  return mesh;
}

}  // namespace

std::vector<std::string> GmshMesh::group_names(int dim) const {
  std::vector<std::string> names;
  for (const MeshGroup& g : groups) {
    if (g.dim == dim)
      names.push_back(g.name);
  }
  std::sort(names.begin(), names.end());
  names.erase(std::unique(names.begin(), names.end()), names.end());
  return names;
}

GmshMesh parse_gmsh_mesh(const std::string& text, const std::string& name) {
  Cursor cursor(text, name);
  return assemble(read_sections(cursor), name);
}

GmshMesh read_gmsh_mesh(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(path, 0, "", "cannot open the mesh file: no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "", "cannot open the mesh file: it is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, 0, "", "cannot open the mesh file (is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw InputError(path, 0, "", "cannot read the mesh file");
  return parse_gmsh_mesh(text.str(), path);
}

}  // namespace bimrock
