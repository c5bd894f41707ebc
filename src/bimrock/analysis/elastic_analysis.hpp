#pragma once
/// @file Linear elastic analysis of the block-interfaces model: K U = P (eq. 14).
#include <string>
#include <vector>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/timings.hpp>

namespace bimrock {

struct ElasticSolution {
  Eigen::VectorXd u;  ///< all block unknowns
  std::vector<BlockState> blocks;
  std::vector<InterfaceState> interfaces;
  std::vector<SpringState> springs;  ///< per bolt spring (a nonlinear analysis' stage)
  Eigen::Vector3d mean_strain = Eigen::Vector3d::Zero();
  std::vector<Vec2> monitor_displacements;  ///< in the order of Model::monitors
  long factor_nonzeros = 0;
  Timings timings;
};

/// Checks the supports, assembles and factorizes K, solves for the model's loads and evaluates
/// every block and interface. Throws ModelError when the structure is not fully supported.
ElasticSolution solve_elastic(const Model& model);

/// Evaluates block, interface and monitor results of the displacement vector solution.u, less
/// the plastic parts of a nonlinear analysis where given.
void evaluate_fields(const Model& model, ElasticSolution& solution,
                     const PlasticParts& plastic = {});

}  // namespace bimrock
