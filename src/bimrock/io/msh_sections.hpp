#pragma once
/// @file Internal to the gmsh reader (gmsh_mesh.hpp; not part of the public API): the sections of
/// an MSH 4.1 ASCII file read as they are ($MeshFormat, $PhysicalNames, $Entities, $Nodes,
/// $Elements; others skipped), each entry checked for its syntax and its line kept. Whether the
/// nodes and elements make a mesh of blocks is gmsh_mesh.cpp's to check.
#include <cstdint>
#include <map>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include <bimrock/geometry/vec2.hpp>
#include <bimrock/io/msh_lines.hpp>

namespace bimrock::msh {

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

/// Reads the file from its first line: every section, up to the end. Throws InputError.
[[nodiscard]] Parsed read_sections(Cursor& c);

}  // namespace bimrock::msh
