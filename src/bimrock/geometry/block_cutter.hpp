#pragma once
/// @file Cutting a rock domain into convex blocks along joint traces.
///
/// The outline, holes, zone outlines and traces are overlaid in one exact arrangement (CGAL,
/// exact constructions: every crossing is found and placed exactly, however close). Then:
///  1. a trace ending inside rock is extended to the next edge (a rock bridge), so each joint
///     piece separates two blocks;
///  2. holes no trace reaches are joined to the rest by vertical rock-bridge cuts; the regions
///     are now simple polygons;
///  3. regions that are not convex (a notch of the outline, a hole, a zone corner) are split into
///     convex pieces by CGAL's optimal convex partition (Greene; Hertel-Mehlhorn above
///     `max_optimal_partition_vertices` corners); pieces of one region share `face`;
///  4. blocks smaller than `min_block_area` (slivers) are merged into a neighbour with which
///     their union is still convex, never dropped; those with no such neighbour are kept and
///     counted (n_slivers_kept); a merged face found non-convex beyond the tolerance after all
///     (round-off on slivers 1e-15 wide) is partitioned again; n_small_blocks counts what is
///     left below min_block_area.
/// Each arrangement vertex is converted to doubles once, so neighbouring blocks share the exact
/// same coordinates. The arrangement is built by one sweep: O((n + k) log n) for n traces and
/// k crossings.
/// @note Exact arithmetic removes zero-area slivers but not short edges: where joints nearly
///       meet, a block may keep an edge shorter than model_tolerance() (see the tests).
#include <cstdint>
#include <span>
#include <vector>

#include <bimrock/geometry/domain.hpp>
#include <bimrock/geometry/joint_set.hpp>

namespace bimrock {

/// What separates two blocks along a cut edge (or a block from the outside).
enum class EdgeKind : std::uint8_t {
  boundary,       ///< the domain outline or a hole: one side is outside
  joint,          ///< on a joint trace (see CutEdge::trace for its material)
  zone_boundary,  ///< on a zone outline, no joint: a contact between two rock materials
  rock_bridge,    ///< a cut through intact rock: a joint extended, or a cut from a hole
  partition,      ///< a diagonal between convex pieces of one non-convex face
};

struct CutBlock {
  Polygon polygon;              ///< convex, counter-clockwise, no collinear vertices
  std::vector<int> vertex_ids;  ///< into BlockCut::vertices, one per polygon vertex
  /// The region this block is a piece of: blocks with the same `face` were one region bounded by
  /// joints, outlines and rock bridges, split only to make them convex (partition edges
  /// between them are not joints). A merged sliver takes its neighbour's region.
  int face = 0;
  int zone = -1;  ///< index into Domain::zones, -1 outside every zone
};

/// A straight piece of block boundary between two arrangement vertices. A block side may hold
/// several pieces (a T-junction where a neighbour's corner touches it); every piece has one
/// kind and one block on each side.
struct CutEdge {
  int a = 0;  ///< vertex id where it starts
  int b = 0;  ///< vertex id where it ends; `left` lies on the left of a -> b
  int left = -1;
  int right = -1;  ///< block ids; -1 outside the domain or in a hole
  EdgeKind kind = EdgeKind::boundary;
  int trace = -1;  ///< the joint trace it lies on (lowest index if several), or -1
};

struct CutOptions {
  /// Blocks with a smaller area (m^2) are merged into a neighbour; 0 merges nothing. See
  /// suggested_min_block_area() in joint_set.hpp for a value relative to the spacing.
  double min_block_area = 0.0;
  /// Non-convex faces with more corners use the linear-time Hertel-Mehlhorn partition (at most
  /// 4 times the optimal number of pieces) instead of the O(n^4) optimal one.
  int max_optimal_partition_vertices = 40;
};

/// What the cutter did, for the run report.
struct CutStats {
  int n_traces = 0;               ///< traces inserted (zero-length ones skipped)
  int n_faces = 0;                ///< regions inside the domain before partition and merge
  int n_partitioned_faces = 0;    ///< non-convex regions split into convex pieces
  int n_rock_bridges = 0;         ///< dangling trace ends extended through rock
  int n_hole_cuts = 0;            ///< vertical cuts joining holes to the rest
  int n_slivers_merged = 0;       ///< blocks below min_block_area merged into a neighbour
  int n_slivers_kept = 0;         ///< blocks below min_block_area with no convex merge (kept)
  int n_joint_edges_removed = 0;  ///< joint pieces that became intact rock in a merge
  int n_small_blocks = 0;         ///< blocks still below min_block_area in the result
};

struct BlockCut {
  std::vector<Vec2> vertices;  ///< every block corner and edge end, converted once
  std::vector<CutBlock> blocks;
  std::vector<CutEdge> edges;
  CutStats stats;
};

/// Cuts the domain by the traces. Throws GeometryError for an invalid domain (see validate())
/// or a non-finite trace ("traces[i]").
BlockCut cut_blocks(const Domain& domain, std::span<const JointTrace> traces,
                    const CutOptions& options = {});

/// The block polygons alone, in block order.
std::vector<Polygon> block_polygons(const BlockCut& cut);

}  // namespace bimrock
