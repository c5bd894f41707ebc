#include <bimrock/geometry/brick_pattern.hpp>

namespace bimrock {
namespace {

Polygon rectangle(double xa, double ya, double xb, double yb) {
  return {{{xa, ya}, {xb, ya}, {xb, yb}, {xa, yb}}};
}

// Cut points 0 = s_0 < s_1 < ... < s_m = n * size of a line of n cells, shifted by half a
// cell when `shifted`.
std::vector<double> cuts(int n, double size, bool shifted) {
  std::vector<double> s{0.0};
  if (shifted)
    s.push_back(0.5 * size);
  for (int k = 1; k < n; ++k)
    s.push_back((k + (shifted ? 0.5 : 0.0)) * size);
  s.push_back(n * size);
  return s;
}

}  // namespace

std::vector<Polygon> brick_pattern(int nx, int ny, double w, double h, Stagger stagger, Vec2 o) {
  std::vector<Polygon> blocks;
  if (stagger == Stagger::columns) {
    for (int i = 0; i < nx; ++i) {
      const std::vector<double> ys = cuts(ny, h, i % 2 == 1);
      for (std::size_t k = 0; k + 1 < ys.size(); ++k)
        blocks.push_back(
            rectangle(o.x() + i * w, o.y() + ys[k], o.x() + (i + 1) * w, o.y() + ys[k + 1]));
    }
    return blocks;
  }
  for (int j = 0; j < ny; ++j) {
    const std::vector<double> xs = cuts(nx, w, stagger == Stagger::rows && j % 2 == 1);
    for (std::size_t k = 0; k + 1 < xs.size(); ++k)
      blocks.push_back(
          rectangle(o.x() + xs[k], o.y() + j * h, o.x() + xs[k + 1], o.y() + (j + 1) * h));
  }
  return blocks;
}

}  // namespace bimrock
