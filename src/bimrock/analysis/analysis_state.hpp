#pragma once
/// @file The state a plastic analysis carries from increment to increment.
#include <array>
#include <map>
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/plastic_state.hpp>

namespace bimrock {

/// The relative displacement [delta_n, delta_s] of each of an interface's two integration points
/// when a stage installed one of its blocks, by interface index: its stress counts from there.
using InstalledInterfaces = std::map<int, std::array<Eigen::Vector2d, 2>>;

struct AnalysisState {
  Eigen::VectorXd u;                 ///< total block unknowns
  std::vector<PlasticState> points;  ///< per yield point
  InstalledInterfaces installed;     ///< the interfaces of installed blocks
  double stage_factor = 0.0;         ///< fraction of the current stage's loads applied
};

}  // namespace bimrock
