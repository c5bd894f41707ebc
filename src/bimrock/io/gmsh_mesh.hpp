#pragma once
/// @file Reading a gmsh 2D mesh (MSH 4.1 ASCII) as the cells of a block model: its 3-node
/// triangles and 4-node quadrangles (each checked to be a convex, counter-clockwise polygon),
/// its 2-node line elements, and the physical groups they belong to. A pure parser: it knows
/// nothing of materials or supports; the case reader maps the groups onto them.
///
/// Format: https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format (version 4.1). Read:
/// $MeshFormat, $PhysicalNames, $Entities, $Nodes, $Elements. Other sections ($Periodic,
/// $NodeData, $Comments, ...) cannot change the nodes or elements and are skipped, as the format
/// prescribes; $PartitionedEntities (a partitioned mesh) is refused. Units: SI (m).
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {

/// A physical group: gmsh's `Physical Surface` (dim 2) or `Physical Curve` (dim 1).
struct MeshGroup {
  int dim = 0;
  int tag = 0;
  /// From $PhysicalNames; a group without a name is called by its tag ("7").
  std::string name;
};

/// A 3-node triangle or 4-node quadrangle of a surface entity.
struct MeshCell {
  std::int64_t tag = 0;             ///< element tag
  int surface = 0;                  ///< tag of its surface entity
  std::vector<std::int64_t> nodes;  ///< node tags in the file's order (counter-clockwise)
  Polygon polygon;                  ///< the node coordinates [m]: convex, counter-clockwise
  /// The names of the physical surfaces of its entity (empty: none).
  std::vector<std::string> groups;
  int line = 0;  ///< 1-based line of the element in the .msh file
};

/// A 2-node line element of a curve entity (for selecting boundary edges by physical curve).
struct MeshLine {
  std::int64_t tag = 0;
  int curve = 0;  ///< tag of its curve entity
  std::array<std::int64_t, 2> nodes{};
  Segment segment;                  ///< [m]
  std::vector<std::string> groups;  ///< the names of the physical curves of its entity
  int line = 0;
};

struct GmshMesh {
  std::string file;               ///< as given, for error messages
  std::vector<MeshGroup> groups;  ///< every physical group named in the file or used by an entity
  std::vector<MeshCell> cells;    ///< in the file's order
  std::vector<MeshLine> lines;

  /// The names of the groups of one dimension (2: surfaces, 1: curves), sorted, unique.
  [[nodiscard]] std::vector<std::string> group_names(int dim) const;
};

/// Reads a .msh file. Throws InputError naming the file, the line and the item (element, node,
/// section) for anything it cannot take: another version or a binary file, a malformed line,
/// elements other than first-order lines, triangles and quadrangles (and points, which are
/// ignored), a node off the plane z = 0, and cells that are clockwise (inverted), degenerate
/// (a repeated node, coinciding nodes, zero area to the model's tolerance) or non-convex.
/// Cells are never silently reordered.
GmshMesh read_gmsh_mesh(const std::string& path);

/// The same from text; `name` stands for the file in error messages.
GmshMesh parse_gmsh_mesh(const std::string& text, const std::string& name);

}  // namespace bimrock
