#pragma once
/// @file The blocks of a case given by its domain and joint sets: cut by the joint
/// traces (geometry/block_cutter), optionally subdivided into Voronoi cells, each block with its
/// zone's material, and for each pair of touching blocks the joint material between them.
#include <map>
#include <utility>
#include <vector>

#include <bimrock/geometry/block_cutter.hpp>
#include <bimrock/model/case_spec.hpp>

namespace bimrock {

struct GeneratedBlocks {
  std::vector<BlockSpec> blocks;
  std::vector<int> parent;  ///< per block: the cut block it is a cell of (itself if not split)
  /// Joint material between cut blocks i < j: the material of the joint traces along most of
  /// their common edge, or "" where that is a cut through intact rock (rock bridge, convex
  /// partition, zone contact).
  std::map<std::pair<int, int>, std::string> joint_between_parents;
  CutStats stats;
  int subdivided = 0;        ///< cut blocks split into cells
  int degenerate_cells = 0;  ///< blocks and Voronoi cells of zero area (to the tolerance) left out

  /// The joint material between generated blocks i and j ("" : intact rock).
  [[nodiscard]] std::string joint_between(int i, int j) const;
};

/// Throws InputError naming the file, the line and the item of the domain (e.g.
/// "domain.holes[1]") for bad geometry, and for a domain whose joint traces or blocks, estimated
/// before any is generated, would exceed `limits`.
GeneratedBlocks generate_blocks(const DomainSpec& spec, const std::string& file,
                                const CaseLimits& limits = {});

}  // namespace bimrock
