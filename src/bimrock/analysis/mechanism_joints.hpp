#pragma once
/// @file One mode per joint point of a collapse mechanism, from its net motion: the relative
/// displacement of its two blocks in the mechanism (Collapse::direction), which is what a user
/// sees, or where there is no direction, the net plastic flow of its active yield modes. A
/// hinge whose slip+ and slip- flows cancel reads as the opening it is.
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/yield_points.hpp>

namespace bimrock {

enum class JointMotion {
  none,  ///< no relative motion above the threshold (e.g. the pivot of a toppling block)
  opening,
  slip_positive,          ///< delta_s > 0: block j slides along +s = (-n_y, n_x) past block i
  slip_negative,          ///< delta_s < 0
  slip_positive_opening,  ///< slip+ with opening
  slip_negative_opening,  ///< slip- with opening
};

/// "none", "opening", "slip+", "slip-", "slip+ with opening", "slip- with opening".
[[nodiscard]] const char* joint_motion_name(JointMotion m);

/// A part of a joint point's motion counts when it exceeds this fraction of the point's own
/// relative motion |delta| (and the absolute threshold of classify_joint_motion).
inline constexpr double kJointPartFraction = 1e-2;

/// The mode of a joint point moving by delta = [normal, shear] (normal > 0 opens): the normal
/// part counts as opening when it is > threshold, the shear part as slip of its sign when its
/// magnitude is > threshold, with threshold = max(absolute, kJointPartFraction |delta|).
[[nodiscard]] JointMotion classify_joint_motion(const Eigen::Vector2d& delta, double absolute);

/// The net plastic flow [normal, shear] of a joint point's active modes: slip+ flows along
/// (tan psi, +1), slip- along (tan psi, -1), opening along (1, 0), each times its multiplier.
/// @param multipliers of slip+, slip-, opening (kOpeningMode), in that order
[[nodiscard]] Eigen::Vector2d net_plastic_flow(const Eigen::Vector3d& multipliers,
                                               double tan_dilation);

struct MechanismJoint {
  int point = 0;                                    ///< yield point index
  Eigen::Vector2d delta = Eigen::Vector2d::Zero();  ///< [normal, shear], normalized
  JointMotion motion = JointMotion::none;
};

/// Every joint point of the collapse's mechanism, in the order of its first entry there.
/// @param scale what `direction` is divided by for the relative displacements (the fastest
///   block corner: mechanism_blocks()); with no direction (or scale 0) the net plastic flow of
///   the point's multipliers (the largest 1) is used instead
/// The absolute threshold is MechanismBlock's standing fraction (1e-3 of the fastest corner).
[[nodiscard]] std::vector<MechanismJoint> mechanism_joints(const Model& model,
                                                           const std::vector<YieldPoint>& points,
                                                           const Collapse& collapse, double scale);

}  // namespace bimrock
