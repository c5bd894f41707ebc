#pragma once
/// @file Excavation (docs/formulation.md, "Excavation"): the forces the excavated blocks exerted
/// on the blocks that remain. Once the blocks and their interfaces are gone, the remaining
/// blocks' internal forces lack these terms; a stage applies them, as a load, over its
/// increments (all of them, or the `release` fraction and the rest later): the stress that the
/// excavated rock carried is released onto the rest.
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/model/stage_blocks.hpp>  // blocks_present

namespace bimrock {

/// The forces [N] on the unknowns of the blocks flagged in `present` (after the excavation) of
/// every interface between one of them and an `excavated` block: t integral B^T R ds in the
/// state (u, plastic). R's initial part is integrated by 2 Gauss points (exact, it is linear),
/// the rest at the interface's own integration points, as K and the plastic loads integrate it,
/// so that the forces released are exactly those the remaining blocks' equilibrium held.
Eigen::VectorXd excavation_forces(const Model& model, const std::vector<char>& present,
                                  const std::vector<int>& excavated, const Eigen::VectorXd& u,
                                  const PlasticParts& plastic);

}  // namespace bimrock
