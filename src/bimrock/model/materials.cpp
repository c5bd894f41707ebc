#include <bimrock/model/materials.hpp>

namespace bimrock {

Eigen::Matrix3d elasticity_matrix(const BlockMaterial& m, PlaneMode plane) {
  const double e = m.young;
  const double v = m.poisson;
  Eigen::Matrix3d d = Eigen::Matrix3d::Zero();
  if (plane == PlaneMode::strain) {
    const double c = e / ((1.0 + v) * (1.0 - 2.0 * v));
    d << 1.0 - v, v, 0.0, v, 1.0 - v, 0.0, 0.0, 0.0, 0.5 * (1.0 - 2.0 * v);
    return c * d;
  }
  const double c = e / (1.0 - v * v);
  d << 1.0, v, 0.0, v, 1.0, 0.0, 0.0, 0.0, 0.5 * (1.0 - v);
  return c * d;
}

SpringPair layer_stiffness(double young, double poisson, double thickness, PlaneMode plane) {
  const double shear = young / (2.0 * (1.0 + poisson) * thickness);
  if (plane == PlaneMode::stress)
    return {young / ((1.0 - poisson * poisson) * thickness), shear};
  const double constrained = young * (1.0 - poisson) / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  return {constrained / thickness, shear};
}

}  // namespace bimrock
