#pragma once
/// @file Block kinematics (eq. 1) and interface relative displacement (eqs. 3-5), and a bolt
/// spring's, between a point of each of its blocks.
/// Block unknowns d = [u0, v0, theta, eps_x, eps_y, gamma_xy] at the centroid (x0, y0);
/// rotation counter-clockwise positive.
#include <Eigen/Core>

#include <bimrock/geometry/vec2.hpp>

namespace bimrock {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using Mat26 = Eigen::Matrix<double, 2, 6>;
using Mat2x12 = Eigen::Matrix<double, 2, 12>;

/// Q(x, y) of eq. 1: u = Q d at point p of a block with centroid c.
inline Mat26 block_Q(const Vec2& c, const Vec2& p) {
  const double dx = p.x() - c.x();
  const double dy = p.y() - c.y();
  Mat26 q;
  q << 1.0, 0.0, -dy, dx, 0.0, 0.5 * dy,  //
      0.0, 1.0, dx, 0.0, dy, 0.5 * dx;
  return q;
}

/// T of eq. 4: rows are the interface normal n and tangent s = (-n_y, n_x).
inline Eigen::Matrix2d interface_T(const Vec2& n) {
  Eigen::Matrix2d t;
  t << n.x(), n.y(), -n.y(), n.x();
  return t;
}

/// B of eq. 5 at point p: delta = [delta_n, delta_s] = T (Q_j(p) d_j - Q_i(p) d_i) = B [d_i; d_j].
inline Mat2x12 interface_B(const Vec2& n, const Vec2& ci, const Vec2& cj, const Vec2& p) {
  const Eigen::Matrix2d t = interface_T(n);
  Mat2x12 b;
  b.leftCols<6>() = -t * block_Q(ci, p);
  b.rightCols<6>() = t * block_Q(cj, p);
  return b;
}

/// B of a bolt's spring (docs/formulation.md, "Bolts"): delta = T(axis) (Q_b(b) d_b - Q_a(a)
/// d_a) = B [d_a; d_b], its elongation along the axis first, then its shear.
inline Mat2x12 bolt_B(const Vec2& axis, const Vec2& ca, const Vec2& a, const Vec2& cb,
                      const Vec2& b) {
  const Eigen::Matrix2d t = interface_T(axis);
  Mat2x12 out;
  out.leftCols<6>() = -t * block_Q(ca, a);
  out.rightCols<6>() = t * block_Q(cb, b);
  return out;
}

/// B of a support at point p: the ground does not move, delta = -T Q_i(p) d_i.
inline Mat26 support_B(const Vec2& n, const Vec2& ci, const Vec2& p) {
  return -interface_T(n) * block_Q(ci, p);
}

}  // namespace bimrock
