#include <bimrock/assembly/initial_forces.hpp>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/model/initial_stress.hpp>

namespace bimrock {

Eigen::VectorXd initial_internal_forces(const Model& model) {
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(model.n_dofs());
  if (!model.initial_stress)
    return forces;
  const double t = model.settings.thickness;
  for (int b = 0; b < model.n_blocks(); ++b)
    forces.segment<3>(6 * b + 3) += t * model.blocks[b].area * block_initial_stress(model, b);
  for (const Interface& f : model.interfaces) {
    const Vec2& ci = model.blocks[f.block_i].centroid;
    for (const IntegrationPoint& ip : integration_points(f.segment, Integration::gauss)) {
      const Eigen::Vector2d r0 = interface_initial_stress(model, f, ip.point);
      if (f.is_support()) {
        forces.segment<6>(6 * f.block_i) +=
            t * ip.weight * support_B(f.normal, ci, ip.point).transpose() * r0;
        continue;
      }
      const Mat2x12 b = interface_B(f.normal, ci, model.blocks[f.block_j].centroid, ip.point);
      forces.segment<6>(6 * f.block_i) += t * ip.weight * b.leftCols<6>().transpose() * r0;
      forces.segment<6>(6 * f.block_j) += t * ip.weight * b.rightCols<6>().transpose() * r0;
    }
  }
  return forces;
}

}  // namespace bimrock
