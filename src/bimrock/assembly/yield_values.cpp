#include <bimrock/assembly/yield_values.hpp>

#include <algorithm>

#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/yield_modes.hpp>

namespace bimrock {

YieldEvaluator::YieldEvaluator(const Model& model, const std::vector<YieldPoint>& points,
                               const Presence* present)
    : model_(model), points_(points), absent_(points.size(), 0) {
  first_.reserve(points.size() + 1);
  first_.push_back(0);
  for (std::size_t k = 0; k < points.size(); ++k) {
    const YieldPoint& p = points[k];
    first_.push_back(first_.back() + n_modes(model, p));
    if (present)
      absent_[k] = !point_present(p, *present);
  }
  block_laws_.resize(model.block_materials.size());
  for (std::size_t m = 0; m < model.block_materials.size(); ++m) {
    const BlockMaterial& material = model.block_materials[m];
    if (!material.strength)
      continue;
    const BlockPlanes planes = block_planes(*material.strength);
    block_laws_[m] = {elasticity_matrix(material, model.settings.plane), planes.a, planes.strength};
  }
}

void YieldEvaluator::evaluate(const std::vector<PlasticState>& states, const Eigen::VectorXd& u,
                              YieldValues& out, double* scale) const {
  out.first = first_;
  out.f.resize(first_.back());
  double largest = 0.0;
  for (std::size_t p = 0; p < points_.size(); ++p) {
    const YieldPoint& point = points_[p];
    const PlasticState& s = states[p];
    const Eigen::Index at = first_[p];
    if (absent_[p]) {
      out.f.segment(at, first_[p + 1] - at).setConstant(kAbsentPoint);
      continue;
    }
    const Vec2& ci = model_.blocks[point.block_i].centroid;
    const Vec6 di = u.segment<6>(6 * point.block_i);
    if (point.is_bolt()) {
      const Eigen::Vector2d force = local_stress(model_, point, s, u);
      const Bolt& bolt = bolt_of(model_, point);
      out.f.segment(at, first_[p + 1] - at) = bolt_values(bolt, force(0), force(1));
      if (scale)
        largest = std::max({largest, force.cwiseAbs().maxCoeff(), bolt.capacity,
                            bolt.shear_capacity.value_or(0.0)});
    } else if (point.is_interface()) {
      // The relative displacement (eq. 5), less its plastic part, on the springs.
      Eigen::Vector2d delta;
      if (point.block_j == kGround) {
        delta = support_B(point.normal, ci, point.position) * di;
      } else {
        Eigen::Matrix<double, 12, 1> d;
        d << di, u.segment<6>(6 * point.block_j);
        delta =
            interface_B(point.normal, ci, model_.blocks[point.block_j].centroid, point.position) *
            d;
      }
      delta -= s.installed_at;
      const Interface& f = model_.interfaces[point.owner];
      const double sigma_n = point.initial(0) + f.normal_stiffness * (delta(0) - s.plastic(0));
      const double tau = point.initial(1) + f.shear_stiffness * (delta(1) - s.plastic(1));
      const JointStrength& law = *model_.joint_materials[point.material].strength;
      out.f.segment<3>(at) = joint_values(law, s, sigma_n, tau);
      if (scale)
        largest = std::max({largest, std::abs(sigma_n), std::abs(tau),
                            std::abs(law.cohesion.value(s.slip)),
                            std::abs(law.tensile.value(s.max_gap))});
    } else {
      const BlockLaw& law = block_laws_[static_cast<std::size_t>(point.material)];
      const Eigen::Vector3d sigma = point.initial + law.d * (di.tail<3>() - s.plastic);
      out.f.segment(at, law.a.rows()) =
          law.a * sigma - Eigen::VectorXd::Constant(law.a.rows(), law.strength);
      if (scale)
        largest = std::max({largest, sigma.cwiseAbs().maxCoeff(), std::abs(law.strength)});
    }
  }
  if (scale)
    *scale = std::max(*scale, largest);
}

}  // namespace bimrock
