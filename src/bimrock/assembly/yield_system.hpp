#pragma once
/// @file The yield rows of one increment for the candidate yield points (eqs. 22-28):
///   K dU = q + Phi lambda,   nu = -f0 - C dU + N lambda >= 0,  lambda >= 0,  lambda . nu = 0.
/// Row r of a point with weight w is scaled by w, so that for associated flow C = Phi^T and N is
/// symmetric, and the LCP matrix N - C K^-1 Phi is symmetric (docs/formulation.md).
#include <vector>

#include <Eigen/SparseCore>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_modes.hpp>

namespace bimrock {

/// Which yield point and mode a row stands for.
struct YieldRow {
  int point = 0;
  int mode = 0;
};

struct YieldSystem {
  std::vector<YieldRow> rows;
  SparseMatrix phi;    ///< n_dofs x m: plastic loads of unit multipliers
  SparseMatrix c;      ///< m x n_dofs: rate of each (scaled) yield function with dU
  SparseMatrix n;      ///< m x m: local plastic coupling and hardening (block diagonal: the
                       ///< modes of one point are consecutive rows)
  Eigen::VectorXd f0;  ///< m: (scaled) yield function values at the current state
  std::vector<Eigen::Vector3d> flow;  ///< per row: the flow direction g (first 2 for joints)
  [[nodiscard]] int size() const { return static_cast<int>(rows.size()); }
};

/// The flow rule the rows follow: the model's (its dilation angles); the associated one (flow
/// along each yield function's gradient), whose collapse loads bound those of every other flow
/// rule from above (analysis/associated_bound.hpp); or the model's flow with each yield
/// function's gradient turned along it (f0 kept; C = Phi^T and N symmetric), the symmetric part
/// of the splitting of a non-associated LCP (solve/symmetric_splitting.hpp).
enum class FlowRule { as_modelled, associated, gradient_along_flow };

/// Builds the yield rows of every mode of the given yield points at their current state.
/// @param candidates indices into `points`
/// @param toward_gradient turns each flow direction g by this fraction t toward its yield
///        function's gradient a, g + t (a - g), before `flow` applies: 0 keeps the model's, 1
///        is associated flow, and a small t gives an LCP near the model's whose flows are never
///        exactly opposite (solve/increment_lcp.hpp, IncrementLcp::perturbed)
YieldSystem assemble_yield_system(const Model& model, const std::vector<YieldPoint>& points,
                                  const std::vector<PlasticState>& states, const Eigen::VectorXd& u,
                                  const std::vector<int>& candidates,
                                  FlowRule flow = FlowRule::as_modelled,
                                  double toward_gradient = 0.0);

/// Whether the rows follow associated flow, C = Phi^T and N symmetric (to round-off): the LCP
/// matrix N - C K^-1 Phi is then symmetric.
[[nodiscard]] bool follows_associated_flow(const YieldSystem& sys);

}  // namespace bimrock
