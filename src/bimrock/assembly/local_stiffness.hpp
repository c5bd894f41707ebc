#pragma once
/// @file Local stiffness blocks of eq. 14, each with the global indices of its rows.
#include <array>

#include <Eigen/Core>

#include <bimrock/model/model.hpp>

namespace bimrock {

using Mat6 = Eigen::Matrix<double, 6, 6>;
using Mat12 = Eigen::Matrix<double, 12, 12>;

/// t A D_b on the strain unknowns of a block (eq. 10); rigid-motion rows are zero.
Mat6 block_stiffness(const Block& b, const Eigen::Matrix3d& d_b, double thickness);

/// t * integral B^T D_s B ds over an interface between two blocks (eq. 13), integrated with the
/// interface's rule; unknowns ordered [d_i; d_j].
Mat12 interface_stiffness(const Interface& f, const Vec2& ci, const Vec2& cj, double thickness);

/// The same for a support interface (the ground side has no unknowns).
Mat6 support_stiffness(const Interface& f, const Vec2& ci, double thickness);

/// The stiffness of one bolt spring times the bolts in the model's thickness (B^T D B, D =
/// diag(axial, shear)); unknowns ordered [d_a; d_b].
Mat12 bolt_stiffness(const Model& model, const BoltSpring& s);

}  // namespace bimrock
