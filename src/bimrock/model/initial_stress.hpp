#pragma once
/// @file The stress in the rock before the first stage (docs/formulation.md, "Initial stress"):
/// a linear field, the case's uniform part plus a gravitational one, given to every block and
/// interface present at the start. A linear field that satisfies div sigma + b = 0 is in exact
/// equilibrium in the block-interfaces model: a block's mean stress is the field at its centroid
/// and an interface's integral of B^T R is exact with 2 Gauss points, and the principle of
/// virtual work, block by block, turns the pair into the loads (assembly/initial_forces.hpp).
#include <Eigen/Core>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// The stress [sigma_xx, sigma_yy, tau_xy] [Pa] of the field at p (tension positive).
Eigen::Vector3d initial_stress_at(const InitialStressSpec& field, const Vec2& p);

/// [sigma_n, tau] of `sigma` on a plane of unit normal n: the traction sigma n along n and along
/// s = (-n_y, n_x), the interface frame of eq. 4.
Eigen::Vector2d stress_on_plane(const Eigen::Vector3d& sigma, const Vec2& n);

/// A block's initial stress: the field at its centroid (its mean, the field being linear), or 0
/// without a field or for a block installed later.
Eigen::Vector3d block_initial_stress(const Model& model, int block);

/// [sigma_n, tau] of an interface's initial stress at p: the field at p on its plane, or 0
/// without a field or where a block of it is installed later (a new contact starts unstressed).
Eigen::Vector2d interface_initial_stress(const Model& model, const Interface& f, const Vec2& p);

}  // namespace bimrock
