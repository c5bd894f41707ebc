#pragma once
/// @file Regular block patterns: a grid of rectangular blocks with every other row (or column)
/// shifted by half a block, as in a brick wall. Used by examples, verification and benchmarks.
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock {

enum class Stagger {
  none,     ///< a plain grid: both joint sets continuous
  rows,     ///< horizontal joints continuous, vertical joints of odd rows shifted by width/2
  columns,  ///< vertical joints continuous, horizontal joints of odd columns shifted by height/2
};

/// Blocks of a rectangle [x0, x0 + nx w] x [y0, y0 + ny h] of nx x ny cells of size w x h.
/// A staggered line of cells starts and ends with half blocks, so it holds one block more.
/// Blocks are rectangles with counter-clockwise vertices, ordered row by row (or column by
/// column for Stagger::columns).
std::vector<Polygon> brick_pattern(int nx, int ny, double w, double h, Stagger stagger,
                                   Vec2 origin = Vec2::Zero());

}  // namespace bimrock
