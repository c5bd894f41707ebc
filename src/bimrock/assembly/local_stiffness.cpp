#include <bimrock/assembly/local_stiffness.hpp>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/kinematics.hpp>

namespace bimrock {
namespace {

Eigen::Matrix2d spring_matrix(const Interface& f) {
  return Eigen::Vector2d(f.normal_stiffness, f.shear_stiffness).asDiagonal();
}

}  // namespace

Mat6 block_stiffness(const Block& b, const Eigen::Matrix3d& d_b, double thickness) {
  Mat6 k = Mat6::Zero();
  k.bottomRightCorner<3, 3>() = thickness * b.area * d_b;
  return k;
}

Mat12 interface_stiffness(const Interface& f, const Vec2& ci, const Vec2& cj, double thickness) {
  const Eigen::Matrix2d d_s = spring_matrix(f);
  Mat12 k = Mat12::Zero();
  for (const IntegrationPoint& ip : integration_points(f.segment, f.integration)) {
    const Mat2x12 b = interface_B(f.normal, ci, cj, ip.point);
    k.noalias() += (thickness * ip.weight) * b.transpose() * d_s * b;
  }
  return k;
}

Mat6 support_stiffness(const Interface& f, const Vec2& ci, double thickness) {
  const Eigen::Matrix2d d_s = spring_matrix(f);
  Mat6 k = Mat6::Zero();
  for (const IntegrationPoint& ip : integration_points(f.segment, f.integration)) {
    const Mat26 b = support_B(f.normal, ci, ip.point);
    k.noalias() += (thickness * ip.weight) * b.transpose() * d_s * b;
  }
  return k;
}

Mat12 bolt_stiffness(const Model& model, const BoltSpring& s) {
  const Bolt& bolt = model.bolts[static_cast<std::size_t>(s.bolt)];
  const Mat2x12 b =
      bolt_B(s.axis, model.blocks[s.block_a].centroid, s.a, model.blocks[s.block_b].centroid, s.b);
  const Eigen::Matrix2d d =
      Eigen::Vector2d(bolt.axial_stiffness, bolt.shear_stiffness).asDiagonal();
  return bolt.per_model * b.transpose() * d * b;
}

}  // namespace bimrock
