#pragma once
/// @file What a stage adds at its start (docs/formulation.md, "Excavation and installation",
/// "Bolts"): blocks placed unstressed in the displaced structure, bolts jacked to their
/// pretension and locked off. The driver (plastic_analysis.cpp) jacks the pretension as a load
/// increment between the two.
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/analysis_state.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/model/presence.hpp>

namespace bimrock {

/// Installs the blocks stage `st` adds (present in `now`): each interface they share with what
/// stands counts its relative displacement from here (state.installed, and its yield points'
/// installed_at), their yield points start afresh. Returns the loads of the earlier stages on
/// them (their weight), for the stage to apply over its increments.
Eigen::VectorXd install_blocks(const Model& model, const YieldPointIndex& index, int st,
                               const Presence& now, AnalysisState& state);

/// The pretension of the springs installed now (in `now`, not in `before`) as a load on their
/// blocks: what a jack pulling each bolt's head towards its anchor exerts, -w E^T [T0, 0].
Eigen::VectorXd pretension_loads(const Model& model, const std::vector<YieldPoint>& points,
                                 const YieldPointIndex& index, const Presence& before,
                                 const Presence& now);

/// Locks the springs installed now at the displacements state.u: from here each carries its
/// pretension (YieldPoint::initial) plus what its own displacement adds.
void lock_off(const Model& model, const std::vector<YieldPoint>& points,
              const YieldPointIndex& index, const Presence& before, const Presence& now,
              AnalysisState& state);

}  // namespace bimrock
