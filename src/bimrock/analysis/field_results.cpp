#include <bimrock/analysis/field_results.hpp>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/model/initial_stress.hpp>

namespace bimrock {

BlockState block_state(const Model& model, int block, const Eigen::VectorXd& u,
                       const PlasticParts& plastic) {
  const Block& b = model.blocks[block];
  BlockState s;
  s.d = u.segment<6>(6 * block);
  s.strain = s.d.tail<3>();
  if (plastic.index && plastic.index->block_points[block] >= 0)
    s.plastic = (*plastic.states)[plastic.index->block_points[block]].plastic;
  s.stress = block_initial_stress(model, block) +
             elasticity_matrix(model.block_materials[b.material], model.settings.plane) *
                 (s.strain - s.plastic);
  return s;
}

Vec2 displacement_at(const Model& model, int block, const Vec2& p, const Eigen::VectorXd& u) {
  return block_Q(model.blocks[block].centroid, p) * u.segment<6>(6 * block);
}

InterfaceState interface_state(const Model& model, int interface, const Eigen::VectorXd& u,
                               const PlasticParts& plastic) {
  const Interface& f = model.interfaces[interface];
  InterfaceState state;
  const auto points = integration_points(f.segment, f.integration);
  const Eigen::Matrix2d t = interface_T(f.normal);
  for (std::size_t k = 0; k < 2; ++k) {
    const Vec2& p = points[k].point;
    Vec2 jump = -displacement_at(model, f.block_i, p, u);
    if (!f.is_support())
      jump += displacement_at(model, f.block_j, p, u);
    state[k].point = p;
    state[k].delta = t * jump;
    if (plastic.installed) {
      const auto it = plastic.installed->find(interface);
      if (it != plastic.installed->end())
        state[k].delta -= it->second[k];
    }
    if (plastic.index && plastic.index->interface_points[interface][k] >= 0)
      state[k].plastic =
          (*plastic.states)[plastic.index->interface_points[interface][k]].plastic.head<2>();
    const Eigen::Vector2d elastic = state[k].delta - state[k].plastic;
    state[k].stress =
        interface_initial_stress(model, f, p) +
        Eigen::Vector2d(f.normal_stiffness * elastic(0), f.shear_stiffness * elastic(1));
  }
  return state;
}

std::vector<SpringState> spring_states(const Model& model, const std::vector<char>& standing,
                                       const Eigen::VectorXd& u, const PlasticParts& plastic) {
  std::vector<SpringState> out(model.bolt_springs.size());
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (!standing[k] || !plastic.index)
      continue;
    const BoltSpring& s = model.bolt_springs[k];
    const Bolt& bolt = model.bolts[static_cast<std::size_t>(s.bolt)];
    const PlasticState& ps =
        (*plastic.states)[static_cast<std::size_t>(plastic.index->spring_points[k])];
    Eigen::Matrix<double, 12, 1> d;
    d << u.segment<6>(6 * s.block_a), u.segment<6>(6 * s.block_b);
    SpringState& r = out[k];
    r.standing = true;
    r.delta = bolt_B(s.axis, model.blocks[s.block_a].centroid, s.a,
                     model.blocks[s.block_b].centroid, s.b) *
                  d -
              ps.installed_at;
    r.plastic = ps.plastic.head<2>();
    r.force = Eigen::Vector2d(bolt.pretension, 0.0) +
              Eigen::Vector2d(bolt.axial_stiffness, bolt.shear_stiffness)
                  .cwiseProduct(r.delta - r.plastic);
    r.capacity_used = r.force(0) / bolt.capacity;
    r.yielded = ps.slip > 0.0;
  }
  return out;
}

double total_area(const Model& model) {
  double a = 0.0;
  for (const Block& b : model.blocks)
    a += b.area;
  return a;
}

Eigen::Vector3d mean_strain(const Model& model, const Eigen::VectorXd& u) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const BoundaryEdge& e : model.boundary) {
    const Vec2& n = e.outward_normal;
    for (const IntegrationPoint& ip : integration_points(e.segment, Integration::gauss)) {
      const Vec2 d = displacement_at(model, e.polygon, ip.point, u);
      sum +=
          ip.weight * Eigen::Vector3d(d.x() * n.x(), d.y() * n.y(), d.x() * n.y() + d.y() * n.x());
    }
  }
  return sum / total_area(model);
}

}  // namespace bimrock
