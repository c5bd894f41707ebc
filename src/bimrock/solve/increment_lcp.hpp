#pragma once
/// @file One round's LCP of a load increment (eqs. 24-28), as the analysis states it and
/// IncrementSolver solves it: find z >= 0 with w = M z + q >= 0 and z . w = 0, where
///
///   M = N - C K^-1 Phi (+ under displacement control the term that keeps the monitor on its
///       path), q = -f0 - C dU_load,
///
/// over the candidate yield rows. The unknown of an opening row is the total gap, so z = gap_old
/// + lambda and q is shifted by M gap_old. Everything is in the model's unknowns; the solver
/// condenses it onto the zone it solves on.
#include <functional>
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/assembly/yield_system.hpp>

namespace bimrock {

/// The rows of an LCP with each flow direction turned by a fraction t toward its yield
/// function's gradient (assemble_yield_system()'s toward_gradient), and their form along that
/// flow (the symmetric part of its splitting).
struct PerturbedRows {
  YieldSystem rows;
  YieldSystem along_flow;
};

struct IncrementLcp {
  const YieldSystem& rows;                ///< f0, C, Phi, N of the candidate rows
  const std::vector<YieldPoint>& points;  ///< the model's yield points (rows index them)
  Eigen::VectorXd q;                      ///< -f0 - C dU_load, before the shift by the old gaps
  /// Load control: the part of q the step's load makes (-C dU_load). A certificate that no
  /// solution exists then proves the step fails from a fraction of it on (certified_from()).
  /// Empty under displacement control.
  Eigen::VectorXd load_part;
  Eigen::VectorXd gap_old;  ///< per row: the gap before the step (opening rows), else 0
  /// Displacement control: the monitor's row of K's unknowns (u_monitor . direction =
  /// control . U), and the column control_term (= C x_ref / rate) it enters M with. Null: load
  /// control.
  const Eigen::VectorXd* control = nullptr;
  Eigen::VectorXd control_term;
  Eigen::VectorXd warm;  ///< per row: 1 where the solve starts active, else 0
  /// Non-associated flow under load control: the same rows with each yield function's gradient
  /// along its flow (FlowRule::gradient_along_flow), the symmetric part of the splitting that
  /// finds the solve's active set (symmetric_splitting.hpp). Null: none.
  const YieldSystem* along_flow = nullptr;
  /// Non-associated flow under load control: the rows perturbed by a fraction t, assembled on
  /// demand. For small t their LCP is near this one, without its exactly opposite slip flows of
  /// dilation 0; where nothing else has solved this LCP, IncrementSolver follows the solutions
  /// of decreasing t to one of it. Empty: none.
  std::function<PerturbedRows(double t)> perturbed;
};

}  // namespace bimrock
