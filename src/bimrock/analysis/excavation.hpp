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
#include <bimrock/model/presence.hpp>

namespace bimrock {

/// The forces [N] on the unknowns of the blocks present `after` the excavation of every
/// interface between one of them and a block excavated (present `before`, not after): t integral
/// B^T R ds in the state (u, plastic); and of every bolt spring between them, its force
/// (`points`: the analysis' yield points, whose bolt springs hold their installation). R's
/// initial part is integrated by 2 Gauss points (exact, it is linear), the rest at the
/// interface's own integration points, as K and the plastic loads integrate it, so that the
/// forces released are exactly those the remaining blocks' equilibrium held.
Eigen::VectorXd excavation_forces(const Model& model, const Presence& before, const Presence& after,
                                  const Eigen::VectorXd& u, const PlasticParts& plastic,
                                  const std::vector<YieldPoint>& points);

}  // namespace bimrock
