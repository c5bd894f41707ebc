#include <bimrock/io/msh_sections.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string_view>

#include <fmt/core.h>

#include <bimrock/model/limits.hpp>

namespace bimrock::msh {
namespace {

// gmsh element types (gmsh's GmshDefines.h): the ones bimrock keeps, and names for the messages
// about the others.
constexpr int kLine2 = 1;
constexpr int kTriangle3 = 2;
constexpr int kQuadrangle4 = 3;
constexpr int kPoint = 15;

std::string element_type_name(int type) {
  static const std::map<int, std::string> names = {
      {1, "2-node line"},
      {2, "3-node triangle"},
      {3, "4-node quadrangle"},
      {4, "4-node tetrahedron"},
      {5, "8-node hexahedron"},
      {6, "6-node prism"},
      {7, "5-node pyramid"},
      {8, "3-node second-order line"},
      {9, "6-node second-order triangle"},
      {10, "9-node second-order quadrangle"},
      {11, "10-node second-order tetrahedron"},
      {15, "1-node point"},
      {16, "8-node second-order quadrangle"},
      {20, "9-node third-order incomplete triangle"},
      {21, "10-node third-order triangle"},
      {26, "4-node third-order line"},
      {36, "16-node third-order quadrangle"},
  };
  const auto it = names.find(type);
  return "type " + std::to_string(type) + (it == names.end() ? "" : " (" + it->second + ")");
}

void read_format(Cursor& c) {
  const std::string section = "$MeshFormat";
  const Words w = c.words(section);
  w.expect_count(3, section, "'version file-type data-size'");
  const std::string version(w[0]);
  if (version != "4.1") {
    w.fail(section,
           "MSH version " + version +
               " is not supported: bimrock reads MSH 4.1 ASCII (in gmsh: `Mesh.MshFileVersion = "
               "4.1;` in the .geo, or `gmsh -2 -format msh41 file.geo`)");
  }
  if (w[1] != "0") {
    w.fail(section,
           "a binary MSH file: bimrock reads ASCII files (in gmsh: `Mesh.Binary = 0;`, or "
           "save without -bin)");
  }
  c.expect_end(section);
}

void read_physical_names(Cursor& c, Parsed& p) {
  const std::string section = "$PhysicalNames";
  const int n = c.words(section).count(0, section, "the number of physical names");
  for (int k = 0; k < n; ++k) {
    const std::string_view l = c.next(section);
    const Words w(l, c.file(), c.line());
    w.expect_count(3, section, "'dimension tag \"name\"'", true);
    const int dim = w.count(0, section, "the dimension");
    const int tag = w.count(1, section, "the physical tag");
    // The name is the rest of the line, in double quotes; it may hold spaces.
    const std::size_t open = l.find('"');
    const std::size_t close = l.rfind('"');
    if (open == std::string_view::npos || close == open)
      w.fail(section,
             "the name of physical group " + std::to_string(tag) + " must be in double quotes");
    const std::string name(l.substr(open + 1, close - open - 1));
    if (name.empty())
      w.fail(section, "physical group " + std::to_string(tag) + " has an empty name");
    p.names[{dim, tag}] = name;
  }
  c.expect_end(section);
}

/// Each entity line: its tag, then (points) x y z or (others) a bounding box, then its physical
/// tags, then (others) its bounding entities, which are not needed.
void read_entities(Cursor& c, Parsed& p) {
  const std::string section = "$Entities";
  const Words header = c.words(section);
  header.expect_count(4, section, "'numPoints numCurves numSurfaces numVolumes'");
  for (int dim = 0; dim < 4; ++dim) {
    const int n = header.count(static_cast<std::size_t>(dim), section, "a number of entities");
    for (int k = 0; k < n; ++k) {
      const Words w = c.words(section);
      const std::size_t first = dim == 0 ? 4 : 7;  // after the tag and x y z or the box
      w.expect_count(first + 1, section, "an entity", true);
      const int tag = w.count(0, section, "the entity tag");
      const int n_groups = w.count(first, section, "the number of physical tags");
      w.expect_count(first + 1 + static_cast<std::size_t>(n_groups), section, "an entity", true);
      std::vector<int>& groups = p.entity_groups[{dim, tag}];
      for (int g = 0; g < n_groups; ++g) {
        // Physical tags of an entity are written with a sign by some versions; the group is
        // the absolute value.
        const std::int64_t t =
            w.integer(first + 1 + static_cast<std::size_t>(g), section, "a physical tag");
        groups.push_back(static_cast<int>(std::abs(t)));
      }
    }
  }
  c.expect_end(section);
}

/// Blocks of nodes, each: a header, the node tags (one per line), then their coordinates.
void read_nodes(Cursor& c, Parsed& p) {
  const std::string section = "$Nodes";
  const Words header = c.words(section);
  header.expect_count(4, section, "'numEntityBlocks numNodes minNodeTag maxNodeTag'");
  const int blocks = header.count(0, section, "the number of entity blocks");
  // Counts from the file are not trusted for allocations: a corrupt header must give a message,
  // not exhaust memory.
  constexpr int kReserveAtMost = 1 << 20;
  p.nodes.reserve(static_cast<std::size_t>(
      std::min(header.count(1, section, "the number of nodes"), kReserveAtMost)));
  for (int b = 0; b < blocks; ++b) {
    const Words h = c.words(section);
    h.expect_count(4, section, "'entityDim entityTag parametric numNodesInBlock'");
    const int n = h.count(3, section, "the number of nodes in the block");
    std::vector<std::int64_t> tags;
    tags.reserve(static_cast<std::size_t>(std::min(n, kReserveAtMost)));
    for (int k = 0; k < n; ++k) {
      const Words w = c.words(section);
      w.expect_count(1, section, "a node tag");
      tags.push_back(w.integer(0, section, "a node tag"));
    }
    for (const std::int64_t t : tags) {
      const std::string item = "node " + std::to_string(t);
      const Words w = c.words(section);
      w.expect_count(3, item, "its coordinates 'x y z'", true);  // parametric u, v may follow
      Node node{{w.real(0, item, "x"), w.real(1, item, "y")}, w.real(2, item, "z"), c.line()};
      if (std::abs(node.xy.x()) > kMaxCoordinate || std::abs(node.xy.y()) > kMaxCoordinate) {
        w.fail(item, fmt::format("coordinates must lie within +-{:g} m, not [{:g}, {:g}] (as a "
                                 "case file's; are the units metres?)",
                                 kMaxCoordinate, node.xy.x(), node.xy.y()));
      }
      if (!p.nodes.emplace(t, node).second)
        w.fail(item, "the node tag is used twice");
    }
  }
  c.expect_end(section);
}

/// Blocks of elements, each: a header (entity dimension and tag, element type, count), then one
/// element per line: its tag and its node tags.
void read_elements(Cursor& c, Parsed& p) {
  const std::string section = "$Elements";
  const Words header = c.words(section);
  header.expect_count(4, section, "'numEntityBlocks numElements minElementTag maxElementTag'");
  const int blocks = header.count(0, section, "the number of entity blocks");
  for (int b = 0; b < blocks; ++b) {
    const Words h = c.words(section);
    h.expect_count(4, section, "'entityDim entityTag elementType numElementsInBlock'");
    const int dim = h.count(0, section, "the entity dimension");
    const int entity = h.count(1, section, "the entity tag");
    const int type = h.count(2, section, "the element type");
    const int n = h.count(3, section, "the number of elements in the block");
    static const std::map<int, std::pair<int, std::size_t>> kept = {
        {kPoint, {0, 1}}, {kLine2, {1, 2}}, {kTriangle3, {2, 3}}, {kQuadrangle4, {2, 4}}};
    const auto kind = kept.find(type);
    for (int k = 0; k < n; ++k) {
      const Words w = c.words(section);
      const std::int64_t tag = w.integer(0, section, "an element tag");
      const std::string item = "element " + std::to_string(tag) +
                               (dim == 2   ? " (surface " + std::to_string(entity) + ")"
                                : dim == 1 ? " (curve " + std::to_string(entity) + ")"
                                           : "");
      if (dim == 3) {
        w.fail(item, "a 3D element (" + element_type_name(type) +
                         "): bimrock reads 2D meshes of the x-y plane (mesh with `gmsh -2`)");
      }
      if (kind == kept.end()) {
        w.fail(item, "element " + element_type_name(type) +
                         " is not supported: bimrock reads first-order 3-node triangles and "
                         "4-node quadrangles (and 2-node lines); mesh with `Mesh.ElementOrder = "
                         "1;`");
      }
      if (kind->second.first != dim) {
        w.fail(item, "element " + element_type_name(type) + " on an entity of dimension " +
                         std::to_string(dim));
      }
      w.expect_count(1 + kind->second.second, item,
                     "the element tag and its node tags for its type");
      if (type == kPoint)
        continue;
      RawElement e{tag, dim, entity, type, {}, c.line()};
      for (std::size_t v = 0; v < kind->second.second; ++v)
        e.nodes.push_back(w.integer(1 + v, item, "a node tag"));
      p.elements.push_back(std::move(e));
    }
  }
  c.expect_end(section);
}

}  // namespace

Parsed read_sections(Cursor& c) {
  const std::optional<std::string_view> first = c.next_or_end();
  if (!first)
    c.fail("", "the mesh file is empty");
  if (*first != "$MeshFormat")
    c.fail("", "not a gmsh mesh: an MSH file starts with '$MeshFormat'");
  read_format(c);
  Parsed p;
  while (const std::optional<std::string_view> l = c.next_or_end()) {
    const std::string section(*l);
    if (section.empty() || section.front() != '$' || section.rfind("$End", 0) == 0)
      c.fail("", "expected the start of a section ($Nodes, $Elements, ...), found '" +
                     section.substr(0, 40) + "'");
    if (section == "$MeshFormat") {
      c.fail(section, "given twice");
    } else if (section == "$PhysicalNames") {
      read_physical_names(c, p);
    } else if (section == "$Entities") {
      read_entities(c, p);
    } else if (section == "$PartitionedEntities") {
      c.fail(section, "a partitioned mesh: mesh again without partitioning (no `-part`)");
    } else if (section == "$Nodes") {
      if (p.has_nodes)
        c.fail(section, "given twice");
      p.has_nodes = true;
      read_nodes(c, p);
    } else if (section == "$Elements") {
      if (p.has_elements)
        c.fail(section, "given twice");
      p.has_elements = true;
      read_elements(c, p);
    } else {
      c.skip(section);  // the format says: sections with other names are ignored
    }
  }
  if (!p.has_nodes)
    c.fail("$Nodes", "missing: the file has no nodes");
  if (!p.has_elements)
    c.fail("$Elements", "missing: the file has no elements");
  return p;
}

}  // namespace bimrock::msh
