#pragma once
/// @file The plastic state of one yield point, kept apart from the laws.
#include <Eigen/Core>

namespace bimrock {

struct PlasticState {
  /// Interfaces: plastic relative displacement [delta_n^p, delta_s^p] (first 2 entries) [m];
  /// blocks: plastic strain [eps_x, eps_y, gamma_xy].
  Eigen::Vector3d plastic = Eigen::Vector3d::Zero();
  double slip = 0.0;     ///< accumulated plastic slip (or plastic multiplier of a block) kappa
  double gap = 0.0;      ///< interfaces: current reversible opening (>= 0) [m]
  double max_gap = 0.0;  ///< interfaces: the largest opening so far, softens sigma_t [m]
  /// Bolt springs and the interface points of installed blocks: the relative displacement at
  /// installation [m] ([elongation, shear], [delta_n, delta_s]), from which the point's own
  /// displacement counts.
  Eigen::Vector2d installed_at = Eigen::Vector2d::Zero();
};

}  // namespace bimrock
