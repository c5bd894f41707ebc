#pragma once
/// @file The state the stages start from (docs/formulation.md, "Initial stress"): no
/// displacement, and the initial stress of the model (model/initial_stress.hpp). Where it
/// violates a strength and the case allows it, the point's stress is brought back onto its
/// yield surface by an initial plastic part, and the forces that this leaves unbalanced are
/// applied by the first stage: the stress a strength cannot hold is redistributed over the
/// first stage's increments, as in an explicit code's first steps to equilibrium.
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/analysis_state.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/analysis/plastic_options.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

/// What the initial stress balances: the first stage's loads less its internal forces, and the
/// yield points where it violates a strength (by more than the yield tolerance). Throws
/// ModelError naming them unless the case lets them yield (initial_stress.allow_yield).
InitialStressCheck check_initial_stress(const Model& model, const std::vector<YieldPoint>& points,
                                        const PlasticOptions& options);

/// The state before the first stage: u = 0, and at each point whose initial stress violates its
/// strength the plastic part that brings it onto the yield surface (a joint's shear to its
/// Mohr-Coulomb limit and its normal stress to its tension cut-off, which opens it; a block's
/// deviator scaled down to its criterion's polygon). `unbalanced` gets the forces those
/// plastic parts release, sum of w E^T D plastic (the plastic loads of eq. 24).
AnalysisState initial_state(const Model& model, const std::vector<YieldPoint>& points,
                            Eigen::VectorXd& unbalanced);

}  // namespace bimrock
