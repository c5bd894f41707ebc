#pragma once
/// @file The state a plastic analysis carries from increment to increment.
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/plastic_state.hpp>

namespace bimrock {

struct AnalysisState {
  Eigen::VectorXd u;                 ///< total block unknowns
  std::vector<PlasticState> points;  ///< per yield point
  double stage_factor = 0.0;         ///< fraction of the current stage's loads applied
};

}  // namespace bimrock
