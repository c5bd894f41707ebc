#include <bimrock/analysis/mechanism_joints.hpp>

#include <algorithm>
#include <cmath>
#include <map>

#include <bimrock/analysis/mechanism_blocks.hpp>
#include <bimrock/assembly/yield_modes.hpp>

namespace bimrock {

const char* joint_motion_name(JointMotion m) {
  switch (m) {
    case JointMotion::none:
      return "none";
    case JointMotion::opening:
      return "opening";
    case JointMotion::slip_positive:
      return "slip+";
    case JointMotion::slip_negative:
      return "slip-";
    case JointMotion::slip_positive_opening:
      return "slip+ with opening";
    case JointMotion::slip_negative_opening:
      return "slip- with opening";
  }
  return "?";
}

JointMotion classify_joint_motion(const Eigen::Vector2d& delta, double absolute) {
  const double threshold = std::max(absolute, kJointPartFraction * delta.norm());
  const bool opens = delta(0) > threshold;
  const bool slips = std::abs(delta(1)) > threshold;
  if (!slips)
    return opens ? JointMotion::opening : JointMotion::none;
  if (delta(1) > 0.0)
    return opens ? JointMotion::slip_positive_opening : JointMotion::slip_positive;
  return opens ? JointMotion::slip_negative_opening : JointMotion::slip_negative;
}

Eigen::Vector2d net_plastic_flow(const Eigen::Vector3d& multipliers, double tan_dilation) {
  const double slip_positive = multipliers(0);
  const double slip_negative = multipliers(1);
  const double opening = multipliers(kOpeningMode);
  return {tan_dilation * (slip_positive + slip_negative) + opening, slip_positive - slip_negative};
}

std::vector<MechanismJoint> mechanism_joints(const Model& model,
                                             const std::vector<YieldPoint>& points,
                                             const Collapse& collapse, double scale) {
  std::vector<MechanismJoint> joints;
  std::map<int, std::size_t> where;  // point -> index in joints
  std::vector<Eigen::Vector3d> multipliers;
  for (const MechanismEntry& e : collapse.mechanism) {
    const YieldPoint& p = points[static_cast<std::size_t>(e.point)];
    if (!p.is_interface() || e.mode < 0 || e.mode > kOpeningMode)
      continue;
    auto [it, added] = where.try_emplace(e.point, joints.size());
    if (added) {
      joints.push_back({e.point, Eigen::Vector2d::Zero(), JointMotion::none});
      multipliers.push_back(Eigen::Vector3d::Zero());
    }
    multipliers[it->second](e.mode) += e.multiplier;
  }
  const bool moved = collapse.direction.size() == model.n_dofs() && scale > 0.0;
  for (std::size_t k = 0; k < joints.size(); ++k) {
    MechanismJoint& j = joints[k];
    const YieldPoint& p = points[static_cast<std::size_t>(j.point)];
    if (moved) {
      j.delta = local_strain(model, p, collapse.direction) / scale;
    } else {
      const auto& law = model.joint_materials[static_cast<std::size_t>(p.material)].strength;
      j.delta = net_plastic_flow(multipliers[k], law ? law->dilation : 0.0);
    }
    j.motion = classify_joint_motion(j.delta, kStandingFraction);
  }
  return joints;
}

}  // namespace bimrock
