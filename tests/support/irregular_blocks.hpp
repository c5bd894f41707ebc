#pragma once
// Irregular convex blocks for tests: a rectangle cut by pseudo-random straight lines (every cell
// of a line arrangement is convex). Some cuts stop halfway, leaving T-junctions (staggered
// interfaces, one block edge touching several neighbours).
#include <random>
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock::testing {

// Splits a convex polygon by the line through p with normal n; returns the non-empty parts.
inline std::vector<Polygon> split(const Polygon& poly, const Vec2& p, const Vec2& n) {
  Polygon left;
  Polygon right;
  const std::size_t m = poly.size();
  for (std::size_t k = 0; k < m; ++k) {
    const Vec2& a = poly.vertices[k];
    const Vec2& b = poly.vertices[(k + 1) % m];
    const double da = n.dot(a - p);
    const double db = n.dot(b - p);
    (da <= 0.0 ? left : right).vertices.push_back(a);
    if ((da < 0.0 && db > 0.0) || (da > 0.0 && db < 0.0)) {
      const Vec2 x = a + (da / (da - db)) * (b - a);
      left.vertices.push_back(x);
      right.vertices.push_back(x);
    }
  }
  // Keep the polygon whole rather than cut off a sliver (under 5% of its area): the tests want
  // irregular blocks, not degenerate ones.
  const double area = signed_area(poly);
  for (Polygon* q : {&left, &right})
    if (q->size() < 3 || signed_area(*q) < 0.05 * area)
      return {poly};
  return {left, right};
}

// The rectangle [0, w] x [0, h] cut by `n_cuts` lines; every third cut only splits the blocks
// whose centroid lies left of x = w/2 (a T-junction where it stops).
inline std::vector<Polygon> irregular_blocks(double w, double h, int n_cuts, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<Polygon> blocks{{{{0, 0}, {w, 0}, {w, h}, {0, h}}}};
  for (int c = 0; c < n_cuts; ++c) {
    const double y = h * (0.2 + 0.6 * unit(rng));  // y first: draws in a fixed order
    const Vec2 p(w * (0.2 + 0.6 * unit(rng)), y);
    const double angle = M_PI * unit(rng);
    const Vec2 n(std::cos(angle), std::sin(angle));
    const bool partial = c % 3 == 2;
    std::vector<Polygon> next;
    for (const Polygon& b : blocks) {
      if (partial && centroid(b).x() > 0.5 * w) {
        next.push_back(b);
        continue;
      }
      for (Polygon& part : split(b, p, n))
        next.push_back(std::move(part));
    }
    blocks = std::move(next);
  }
  return blocks;
}

}  // namespace bimrock::testing
