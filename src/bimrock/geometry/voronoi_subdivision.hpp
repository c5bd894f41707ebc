#pragma once
/// @file Splitting a large convex block into smaller convex cells: the Voronoi cells of seed
/// points, clipped to the block. Used where a block is too coarse to carry a stress field
/// (the cells are then joined by continuum or "intact rock" interfaces).
#include <cstdint>
#include <span>
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {

enum class SeedPattern {
  random,         ///< uniform in the block
  jittered_grid,  ///< one seed per grid cell of size target_size, moved at random within it
};

struct VoronoiOptions {
  double target_size = 1.0;  ///< cells have about target_size^2 area
  SeedPattern pattern = SeedPattern::jittered_grid;
  double jitter = 0.5;     ///< jittered grid: seeds move by up to jitter * target_size / 2
  std::uint64_t seed = 0;  ///< same seed, same cells; each block draws its own stream
  /// Cells smaller than this fraction of target_size^2 (clipped corners) are merged into a
  /// neighbour by the block cutter.
  double min_cell_fraction = 0.01;
};

struct VoronoiCell {
  Polygon polygon;  ///< convex, counter-clockwise
  int parent = 0;   ///< the block it was cut from
};

/// Cells of one convex block (counter-clockwise). A block holding fewer than 2 seeds comes back
/// whole. Cells of one block share exact vertex coordinates; the block's own corners are kept
/// bit for bit, new points on its sides are T-junctions for its neighbours.
/// @param parent copied into every cell, and mixed into the seed so each block has its own
///        stream (the cells of a block do not depend on which other blocks are split)
/// Throws GeometryError when the options are invalid or the block is not convex.
std::vector<VoronoiCell> voronoi_subdivision(const Polygon& block, int parent,
                                             const VoronoiOptions& options);

/// Splits every block with area above max_area or longer (its diameter) than 2 sqrt(max_area);
/// the others come back whole (parent = index).
std::vector<VoronoiCell> subdivide_large_blocks(std::span<const Polygon> blocks, double max_area,
                                                const VoronoiOptions& options);

}  // namespace bimrock
