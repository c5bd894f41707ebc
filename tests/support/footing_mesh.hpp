#pragma once
// Block meshes for footing problems: a rectangle of square cells, each cut by both diagonals into
// four triangles ("crossed triangles", the "union jack" pattern without alternation). Interfaces
// then run in four directions (0, 45, 90 and 135 degrees), and constant strain triangles in this
// pattern do not lock under isochoric plastic flow (Nagtegaal, Parks and Rice 1974), which the
// blocks of the block-interfaces model are when their interfaces are penalty (continuum) springs.
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock::testing {

/// The rectangle [x0, x0 + nx h] x [y0, y0 + ny h] as 4 nx ny triangles, counter-clockwise,
/// cell by cell (row by row from the bottom), in each cell: bottom, right, top, left.
inline std::vector<Polygon> crossed_triangles(int nx, int ny, double h,
                                              Vec2 origin = Vec2::Zero()) {
  std::vector<Polygon> blocks;
  blocks.reserve(static_cast<std::size_t>(4 * nx * ny));
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      const Vec2 a = origin + h * Vec2(i, j);  // lower left corner
      const Vec2 b = a + Vec2(h, 0.0);
      const Vec2 c = a + Vec2(h, h);
      const Vec2 d = a + Vec2(0.0, h);
      const Vec2 m = a + Vec2(0.5 * h, 0.5 * h);  // the crossing of the diagonals
      blocks.push_back(Polygon{{a, b, m}});
      blocks.push_back(Polygon{{b, c, m}});
      blocks.push_back(Polygon{{c, d, m}});
      blocks.push_back(Polygon{{d, a, m}});
    }
  }
  return blocks;
}

}  // namespace bimrock::testing
