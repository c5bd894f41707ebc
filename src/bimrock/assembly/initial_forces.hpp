#pragma once
/// @file The internal forces of the initial stress (model/initial_stress.hpp): what it carries
/// before any displacement. Virtual work of a block's stress on its strain, t A [0, 0, 0, sigma0],
/// and of an interface's stress on its relative displacement, t integral B^T R0 ds (eqs. 10,
/// 13); the loads it balances are what the first stage need not apply.
#include <Eigen/Core>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// The internal force vector [N] of the initial stress of every block and interface: R0 is
/// linear along an interface and B too, so 2 Gauss points integrate it exactly. Zero without
/// an initial stress.
Eigen::VectorXd initial_internal_forces(const Model& model);

}  // namespace bimrock
