#pragma once
// Random convex blocks for the kernel tests, and the quantities the tests work out on their own
// (area and centroid by a triangle fan, the displacement field of a block from the meaning of its
// six unknowns), so that a kernel is compared with numbers the code under test did not make.
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include <bimrock/geometry/polygon.hpp>

namespace bimrock::testing {

// n vertices in angular order on an ellipse (semi-axes 0.3..2 m, turned by a random angle,
// centred near the origin): convex and counter-clockwise by construction. Consecutive angles
// are at least a quarter of the even spacing apart, so no edge is a sliver.
inline Polygon random_convex_polygon(std::mt19937& rng, int n) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double a = 0.3 + 1.7 * unit(rng);
  const double b = 0.3 + 1.7 * unit(rng);
  const double turn = 2.0 * M_PI * unit(rng);
  const double centre_y = 4.0 * unit(rng) - 2.0;  // y first: draws in a fixed order
  const Vec2 centre(4.0 * unit(rng) - 2.0, centre_y);
  const double spacing = 2.0 * M_PI / n;
  const double start = 2.0 * M_PI * unit(rng);
  Polygon p;
  for (int k = 0; k < n; ++k) {
    const double angle = start + spacing * (k + 0.375 * (unit(rng) - 0.5) * 2.0);
    const Vec2 e(a * std::cos(angle), b * std::sin(angle));
    p.vertices.push_back(centre + Vec2(std::cos(turn) * e.x() - std::sin(turn) * e.y(),
                                       std::sin(turn) * e.x() + std::cos(turn) * e.y()));
  }
  return p;
}

// Area and centroid as the sum over the triangles (v0, vk, vk+1): not the shoelace formula of
// geometry/polygon.cpp.
struct FanMoments {
  double area = 0.0;
  Vec2 centroid = Vec2::Zero();
};
inline FanMoments fan_moments(const Polygon& p) {
  FanMoments m;
  const Vec2& o = p.vertices[0];
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const Vec2 e1 = p.vertices[k] - o;
    const Vec2 e2 = p.vertices[k + 1] - o;
    const double a = 0.5 * (e1.x() * e2.y() - e1.y() * e2.x());
    m.area += a;
    m.centroid += a * (o + p.vertices[k] + p.vertices[k + 1]) / 3.0;
  }
  m.centroid /= m.area;
  return m;
}

// A point strictly inside a convex polygon: a random convex combination of its vertices.
inline Vec2 random_inner_point(std::mt19937& rng, const Polygon& p) {
  std::uniform_real_distribution<double> unit(0.05, 1.0);
  Vec2 sum = Vec2::Zero();
  double total = 0.0;
  for (const Vec2& v : p.vertices) {
    const double w = unit(rng);
    sum += w * v;
    total += w;
  }
  return sum / total;
}

// The outward unit normal of the edge of the counter-clockwise polygon p on whose line both ends
// of s lie (within tol); zero if none does.
inline Vec2 outward_normal_of_edge_holding(const Polygon& p, const Segment& s, double tol = 1e-9) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2 a = p.vertices[k];
    const Vec2 b = p.vertices[(k + 1) % p.size()];
    const Vec2 e = (b - a) / (b - a).norm();
    const auto off = [&](const Vec2& q) {
      return std::abs(e.x() * (q - a).y() - e.y() * (q - a).x());
    };
    if (off(s.a) < tol && off(s.b) < tol)
      return {e.y(), -e.x()};  // the edge's direction turned clockwise
  }
  return Vec2::Zero();
}

// The block's unknowns d = [u0, v0, theta, eps_x, eps_y, gamma_xy] (eq. 1) read as what they
// mean: the displacement of the centroid c, a small rotation theta (counter-clockwise) and the
// symmetric strain tensor [[eps_x, gamma/2], [gamma/2, eps_y]] acting on p - c.
template <class Vector6>
Vec2 block_displacement(const Vec2& c, const Vector6& d, const Vec2& p) {
  const Vec2 r = p - c;
  const Vec2 rotation(-d(2) * r.y(), d(2) * r.x());
  const Vec2 strain(d(3) * r.x() + 0.5 * d(5) * r.y(), 0.5 * d(5) * r.x() + d(4) * r.y());
  return Vec2(d(0), d(1)) + rotation + strain;
}

// The unknowns of a block with centroid c under the affine field u(p) = t + G p: translation
// u(c), rotation the skew part of G, strains its symmetric part (engineering shear strain).
template <class Vector6>
Vector6 affine_unknowns(const Vec2& t, const Eigen::Matrix2d& g, const Vec2& c) {
  Vector6 d;
  const Vec2 uc = t + g * c;
  d << uc.x(), uc.y(), 0.5 * (g(1, 0) - g(0, 1)), g(0, 0), g(1, 1), g(0, 1) + g(1, 0);
  return d;
}

}  // namespace bimrock::testing
