#include <bimrock/analysis/field_results.hpp>

#include <bimrock/assembly/integration_points.hpp>

namespace bimrock {

BlockState block_state(const Model& model, int block, const Eigen::VectorXd& u) {
  const Block& b = model.blocks[block];
  BlockState s;
  s.d = u.segment<6>(6 * block);
  s.strain = s.d.tail<3>();
  s.stress = elasticity_matrix(model.block_materials[b.material], model.settings.plane) * s.strain;
  return s;
}

Vec2 displacement_at(const Model& model, int block, const Vec2& p, const Eigen::VectorXd& u) {
  return block_Q(model.blocks[block].centroid, p) * u.segment<6>(6 * block);
}

InterfaceState interface_state(const Model& model, const Interface& f, const Eigen::VectorXd& u) {
  InterfaceState state;
  const auto points = integration_points(f.segment, f.integration);
  const Eigen::Matrix2d t = interface_T(f.normal);
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec2& p = points[k].point;
    Vec2 jump = -displacement_at(model, f.block_i, p, u);
    if (!f.is_support()) jump += displacement_at(model, f.block_j, p, u);
    state[k].point = p;
    state[k].delta = t * jump;
    state[k].stress = {f.normal_stiffness * state[k].delta(0), f.shear_stiffness * state[k].delta(1)};
  }
  return state;
}

double total_area(const Model& model) {
  double a = 0.0;
  for (const Block& b : model.blocks) a += b.area;
  return a;
}

Eigen::Vector3d mean_strain(const Model& model, const Eigen::VectorXd& u) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const BoundaryEdge& e : model.boundary) {
    const Vec2& n = e.outward_normal;
    for (const IntegrationPoint& ip : integration_points(e.segment, Integration::gauss)) {
      const Vec2 d = displacement_at(model, e.polygon, ip.point, u);
      sum += ip.weight * Eigen::Vector3d(d.x() * n.x(), d.y() * n.y(), d.x() * n.y() + d.y() * n.x());
    }
  }
  return sum / total_area(model);
}

}  // namespace bimrock
