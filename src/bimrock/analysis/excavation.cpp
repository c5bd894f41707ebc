#include <bimrock/analysis/excavation.hpp>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/model/initial_stress.hpp>

namespace bimrock {
namespace {

// t integral B^T R ds of interface f, both blocks' 12 unknowns (6 for a support).
Eigen::Matrix<double, 12, 1> interface_force(const Model& model, int index,
                                             const Eigen::VectorXd& u,
                                             const PlasticParts& plastic) {
  const Interface& f = model.interfaces[index];
  const double t = model.settings.thickness;
  const Vec2& ci = model.blocks[f.block_i].centroid;
  const Vec2& cj = f.is_support() ? ci : model.blocks[f.block_j].centroid;
  const auto b_at = [&](const Vec2& p) {
    Mat2x12 b = interface_B(f.normal, ci, cj, p);
    if (f.is_support())
      b.rightCols<6>().setZero();
    return b;
  };
  Eigen::Matrix<double, 12, 1> force = Eigen::Matrix<double, 12, 1>::Zero();
  for (const IntegrationPoint& ip : integration_points(f.segment, Integration::gauss))
    force +=
        t * ip.weight * b_at(ip.point).transpose() * interface_initial_stress(model, f, ip.point);
  const InterfaceState state = interface_state(model, index, u, plastic);
  const auto rule = integration_points(f.segment, f.integration);
  for (std::size_t k = 0; k < rule.size(); ++k) {
    const Eigen::Vector2d elastic =
        state[k].stress - interface_initial_stress(model, f, state[k].point);
    force += t * rule[k].weight * b_at(state[k].point).transpose() * elastic;
  }
  return force;
}

}  // namespace

Eigen::VectorXd excavation_forces(const Model& model, const Presence& before, const Presence& after,
                                  const Eigen::VectorXd& u, const PlasticParts& plastic,
                                  const std::vector<YieldPoint>& points) {
  std::vector<char> gone(model.blocks.size(), 0);
  for (std::size_t b = 0; b < gone.size(); ++b)
    gone[b] = before.blocks[b] != 0 && after.blocks[b] == 0;
  const std::vector<char>& present = after.blocks;
  Eigen::VectorXd forces = Eigen::VectorXd::Zero(model.n_dofs());
  for (int k = 0; k < model.n_interfaces(); ++k) {
    const Interface& f = model.interfaces[k];
    if (f.is_support())
      continue;
    const auto i = static_cast<std::size_t>(f.block_i);
    const auto j = static_cast<std::size_t>(f.block_j);
    const bool i_stays = present[i] != 0 && gone[j] != 0;
    const bool j_stays = present[j] != 0 && gone[i] != 0;
    if (!i_stays && !j_stays)
      continue;
    const Eigen::Matrix<double, 12, 1> force = interface_force(model, k, u, plastic);
    if (i_stays)
      forces.segment<6>(6 * f.block_i) += force.head<6>();
    else
      forces.segment<6>(6 * f.block_j) += force.tail<6>();
  }
  for (std::size_t s = 0; s < model.bolt_springs.size(); ++s) {
    const BoltSpring& spring = model.bolt_springs[s];
    if (!before.springs[s] || after.springs[s])
      continue;  // absent before, or stands on
    const YieldPoint& p = points[static_cast<std::size_t>(plastic.index->spring_points[s])];
    const Eigen::Vector2d force =
        local_stress(model, p, (*plastic.states)[plastic.index->spring_points[s]], u);
    const Eigen::Matrix<double, 12, 1> on_blocks =
        p.weight * local_operator(model, p).e.transpose() * force;
    if (present[static_cast<std::size_t>(spring.block_a)])
      forces.segment<6>(6 * spring.block_a) += on_blocks.head<6>();
    if (present[static_cast<std::size_t>(spring.block_b)])
      forces.segment<6>(6 * spring.block_b) += on_blocks.tail<6>();
  }
  return forces;
}

}  // namespace bimrock
