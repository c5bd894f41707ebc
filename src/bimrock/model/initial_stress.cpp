#include <bimrock/model/initial_stress.hpp>

#include <algorithm>

#include <bimrock/model/stage_blocks.hpp>  // present_at_start

namespace bimrock {

Eigen::Vector3d initial_stress_at(const InitialStressSpec& field, const Vec2& p) {
  Eigen::Vector3d sigma = field.uniform;
  if (field.gravity) {
    const double depth = std::max(0.0, field.gravity->ground_level - p.y());
    const double vertical = -field.gravity->unit_weight * depth;
    sigma(0) += field.gravity->k0 * vertical;
    sigma(1) += vertical;
  }
  return sigma;
}

Eigen::Vector2d stress_on_plane(const Eigen::Vector3d& sigma, const Vec2& n) {
  const Vec2 traction(sigma(0) * n.x() + sigma(2) * n.y(), sigma(2) * n.x() + sigma(1) * n.y());
  const Vec2 s(-n.y(), n.x());
  return {traction.dot(n), traction.dot(s)};
}

Eigen::Vector3d block_initial_stress(const Model& model, int block) {
  if (!model.initial_stress || !present_at_start(model, block))
    return Eigen::Vector3d::Zero();
  return initial_stress_at(*model.initial_stress, model.blocks[block].centroid);
}

Eigen::Vector2d interface_initial_stress(const Model& model, const Interface& f, const Vec2& p) {
  if (!model.initial_stress || !present_at_start(model, f.block_i) ||
      (!f.is_support() && !present_at_start(model, f.block_j)))
    return Eigen::Vector2d::Zero();
  return stress_on_plane(initial_stress_at(*model.initial_stress, p), f.normal);
}

}  // namespace bimrock
