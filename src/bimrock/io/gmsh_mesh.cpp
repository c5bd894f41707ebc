// The gmsh MSH 4.1 ASCII reader: a cursor over the lines of the file (so every error has its
// line), one function per section, then the checks of the cells as blocks.
#include <bimrock/io/gmsh_mesh.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <bimrock/model/errors.hpp>
#include <bimrock/model/limits.hpp>

namespace bimrock {
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

/// A number as a person writes it: 0.5, 1e-08 (std::to_string would give 0.500000, 0.000000).
std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

/// The whitespace-separated words of one line, with typed access that names what was expected.
class Words {
 public:
  Words(std::string_view line, const std::string& file, int number) : file_(file), number_(number) {
    std::size_t k = 0;
    while (k < line.size()) {
      while (k < line.size() && (line[k] == ' ' || line[k] == '\t'))
        ++k;
      const std::size_t start = k;
      while (k < line.size() && line[k] != ' ' && line[k] != '\t')
        ++k;
      if (k > start)
        words_.push_back(line.substr(start, k - start));
    }
  }

  [[nodiscard]] std::size_t size() const { return words_.size(); }
  [[nodiscard]] std::string_view operator[](std::size_t k) const { return words_[k]; }

  [[noreturn]] void fail(const std::string& item, const std::string& message) const {
    throw InputError(file_, number_, item, message);
  }

  /// Exactly n words (or at least n when `at_least`).
  void expect_count(std::size_t n, const std::string& item, const char* what,
                    bool at_least = false) const {
    if (words_.size() < n || (!at_least && words_.size() > n)) {
      fail(item, std::string("expected ") + what + " (" + (at_least ? "at least " : "") +
                     std::to_string(n) + " values), found " + std::to_string(words_.size()));
    }
  }

  [[nodiscard]] std::int64_t integer(std::size_t k, const std::string& item,
                                     const char* what) const {
    const std::string_view w = at(k, item, what);
    std::int64_t value = 0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (ec != std::errc() || end != w.data() + w.size())
      fail(item,
           std::string("expected ") + what + " (a whole number), found '" + std::string(w) + "'");
    return value;
  }

  /// An int-sized whole number >= 0 (a count or an entity tag).
  [[nodiscard]] int count(std::size_t k, const std::string& item, const char* what) const {
    const std::int64_t value = integer(k, item, what);
    if (value < 0 || value > std::numeric_limits<int>::max())
      fail(item, std::string(what) + " out of range: " + std::to_string(value));
    return static_cast<int>(value);
  }

  [[nodiscard]] double real(std::size_t k, const std::string& item, const char* what) const {
    std::string_view w = at(k, item, what);
    if (!w.empty() && w.front() == '+')
      w.remove_prefix(1);
    double value = 0.0;
    const auto [end, ec] = std::from_chars(w.data(), w.data() + w.size(), value);
    if (ec != std::errc() || end != w.data() + w.size())
      fail(item, std::string("expected ") + what + " (a number), found '" + std::string(w) + "'");
    if (!std::isfinite(value))
      fail(item, std::string(what) + " is not a finite number");
    return value;
  }

 private:
  [[nodiscard]] std::string_view at(std::size_t k, const std::string& item,
                                    const char* what) const {
    if (k >= words_.size())
      fail(item, std::string("expected ") + what + ": the line ends early");
    return words_[k];
  }

  std::vector<std::string_view> words_;
  const std::string& file_;
  int number_;
};

/// The lines of the file, read one at a time; blank lines are skipped, "\r\n" ends are accepted.
class Cursor {
 public:
  Cursor(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }

  /// The next non-blank line, or nothing at the end of the file.
  std::optional<std::string_view> next_or_end() {
    while (pos_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
      std::string_view l = text_.substr(pos_, end - pos_);
      pos_ = end + 1;
      ++line_;
      while (!l.empty() && (l.back() == '\r' || l.back() == ' ' || l.back() == '\t'))
        l.remove_suffix(1);
      while (!l.empty() && (l.front() == ' ' || l.front() == '\t'))
        l.remove_prefix(1);
      if (!l.empty())
        return l;
    }
    return std::nullopt;
  }

  /// The next non-blank line of section `section`; the end of the file there is an error.
  std::string_view next(const std::string& section) {
    const std::optional<std::string_view> l = next_or_end();
    if (!l)
      fail(section, "the file ends inside the section (is it cut short?)");
    if (l->front() == '$')
      fail(section, "the section ends early, at '" + std::string(*l) + "'");
    return *l;
  }

  Words words(const std::string& section) {
    const std::string_view l = next(section);  // first: it advances line_
    return Words(l, file_, line_);
  }

  /// The line that must close `section` ("$EndNodes" for "$Nodes").
  void expect_end(const std::string& section) {
    const std::string end = "$End" + section.substr(1);
    const std::optional<std::string_view> l = next_or_end();
    if (!l || *l != end) {
      fail(section, "expected '" + end + "' here, found " +
                        (l ? "'" + std::string(*l).substr(0, 40) + "'" : "the end of the file") +
                        " (more entries than the section's header announces?)");
    }
  }

  /// Skips a section the reader does not need, up to its end line.
  void skip(const std::string& section) {
    const std::string end = "$End" + section.substr(1);
    const int start = line_;
    while (const std::optional<std::string_view> l = next_or_end()) {
      if (*l == end)
        return;
    }
    throw InputError(file_, start, section, "the section is not closed by '" + end + "'");
  }

  [[noreturn]] void fail(const std::string& item, const std::string& message) const {
    throw InputError(file_, line_, item, message);
  }

 private:
  std::string_view text_;
  std::string file_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

struct Node {
  Vec2 xy = Vec2::Zero();
  double z = 0.0;
  int line = 0;
};

/// An element as read, before its entity's groups and its geometry are looked at.
struct RawElement {
  std::int64_t tag = 0;
  int dim = 0;
  int entity = 0;
  int type = 0;
  std::vector<std::int64_t> nodes;
  int line = 0;
};

struct Parsed {
  std::map<std::pair<int, int>, std::string> names;  ///< (dim, tag) -> name ($PhysicalNames)
  /// (dim, entity tag) -> its physical tags; nothing for an entity $Entities does not list.
  std::map<std::pair<int, int>, std::vector<int>> entity_groups;
  std::unordered_map<std::int64_t, Node> nodes;
  std::vector<RawElement> elements;
  bool has_nodes = false;
  bool has_elements = false;
};

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
        w.fail(item, "coordinates must lie within +-" + number(kMaxCoordinate) + " m, not [" +
                         number(node.xy.x()) + ", " + number(node.xy.y()) +
                         "] (as a case file's; are the units metres?)");
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
