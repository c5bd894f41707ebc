#include <bimrock/analysis/initial_state.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include <bimrock/analysis/support_check.hpp>  // name_blocks
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/initial_forces.hpp>
#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/model/presence.hpp>

namespace bimrock {
namespace {

// [sigma_n, tau] on a joint's Mohr-Coulomb surface with its tension cut-off: sigma_n at most
// sigma_t (and at most the apex c / tan(phi)), then |tau| at most c - sigma_n tan(phi).
Eigen::Vector2d joint_within_strength(const JointStrength& law, const Eigen::Vector2d& r) {
  const double tan_phi = law.friction.value(0.0);
  const double c = law.cohesion.value(0.0);
  double sigma_n = std::min(r(0), law.tensile.value(0.0));
  if (tan_phi > 0.0)
    sigma_n = std::min(sigma_n, c / tan_phi);
  const double limit = std::max(0.0, c - sigma_n * tan_phi);
  return {sigma_n, std::clamp(r(1), -limit, limit)};
}

// A block's stress within its criterion's polygon: the mean stress at most the apex, the
// deviator ((s_x - s_y)/2, tau_xy) scaled down until every plane holds.
Eigen::Vector3d block_within_strength(const BlockStrength& law, const Eigen::Vector3d& sigma) {
  const BlockPlanes planes = block_planes(law);
  const double mean = 0.5 * (sigma(0) + sigma(1));
  const Eigen::Vector3d deviator(0.5 * (sigma(0) - sigma(1)), -0.5 * (sigma(0) - sigma(1)),
                                 sigma(2));
  // a_k . [m, m, 0] is the same for every plane (sin(phi) cos(pi / n) m): the mean stress's
  // share of each, which leaves the deviator the room up to the strength.
  const double per_mean = planes.a.row(0).head<2>().sum();
  const double s = per_mean > 0.0 ? std::min(mean, planes.strength / per_mean) : mean;
  const double room = std::max(0.0, planes.strength - per_mean * s);
  double scale = 1.0;
  for (Eigen::Index k = 0; k < planes.a.rows(); ++k) {
    const double load = planes.a.row(k).dot(deviator);
    if (load > 0.0)
      scale = std::min(scale, room / load);
  }
  return Eigen::Vector3d(s, s, 0.0) + scale * deviator;
}

}  // namespace

InitialStressCheck check_initial_stress(const Model& model, const std::vector<YieldPoint>& points,
                                        const PlasticOptions& options) {
  InitialStressCheck check;
  const Eigen::VectorXd loads = assemble_loads(model, model.stages.front().loads);
  const Eigen::VectorXd internal = initial_internal_forces(model);
  check.residual = (loads - internal).cwiseAbs().maxCoeff();
  const double scale = std::max(loads.cwiseAbs().maxCoeff(), internal.cwiseAbs().maxCoeff());
  check.relative_residual = scale > 0.0 ? check.residual / scale : 0.0;
  const Presence present = presence_at(model, -1);
  const YieldEvaluator yield(model, points, &present);
  YieldValues f;
  double stress_scale = 0.0;
  yield.evaluate(std::vector<PlasticState>(points.size()), Eigen::VectorXd::Zero(model.n_dofs()), f,
                 &stress_scale);
  const double tol = options.yield_tolerance * std::max(stress_scale, 1.0);
  std::vector<int> blocks;
  for (std::size_t p = 0; p < points.size(); ++p) {
    if (f.largest(p) <= tol)
      continue;
    ++check.violated_points;
    blocks.push_back(points[p].block_i);
  }
  if (check.violated_points > 0 && !model.initial_stress->allow_yield) {
    std::sort(blocks.begin(), blocks.end());
    blocks.erase(std::unique(blocks.begin(), blocks.end()), blocks.end());
    throw ModelError(std::to_string(check.violated_points) +
                         " yield points violate their strength under the initial stress, at " +
                         name_blocks(model, blocks) +
                         ": give a field within the strengths, or let them yield in the first "
                         "stage (initial_stress.allow_yield: true)",
                     blocks);
  }
  return check;
}

AnalysisState initial_state(const Model& model, const std::vector<YieldPoint>& points,
                            Eigen::VectorXd& unbalanced) {
  AnalysisState s;
  s.u = Eigen::VectorXd::Zero(model.n_dofs());
  s.points.assign(points.size(), PlasticState{});
  unbalanced = Eigen::VectorXd::Zero(model.n_dofs());
  if (!model.initial_stress || !model.initial_stress->allow_yield)
    return s;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const YieldPoint& point = points[p];
    if (point.is_bolt())
      continue;  // installed at a stage's start, not standing in the initial state
    const Eigen::MatrixXd d = local_stiffness(model, point);
    const Eigen::Index n = d.rows();
    const Eigen::VectorXd initial = point.initial.head(n);
    Eigen::VectorXd held;
    if (point.is_interface())
      held =
          joint_within_strength(*model.joint_materials[point.material].strength, initial.head<2>());
    else
      held =
          block_within_strength(*model.block_materials[point.material].strength, initial.head<3>());
    if (held == initial)
      continue;
    // D plastic = initial - held: the stress the point cannot carry.
    const Eigen::VectorXd released = initial - held;
    PlasticState& ps = s.points[p];
    if (point.is_interface()) {  // D_s = diag(k_n, k_s), both positive where a strength is
      ps.plastic.head<2>() = released.head<2>().cwiseQuotient(d.diagonal().head<2>());
      if (ps.plastic(0) > 0.0) {  // the tension cut-off opened it
        ps.gap = ps.plastic(0);
        ps.max_gap = ps.gap;
      }
    } else {
      ps.plastic = d.ldlt().solve(released);
    }
    const LocalOperator op = local_operator(model, point);
    const Eigen::VectorXd force = point.weight * op.e.transpose() * released;
    for (int k = 0; k < op.n_blocks(); ++k)
      unbalanced.segment<6>(6 * op.blocks[k]) += force.segment<6>(6 * k);
  }
  return s;
}

}  // namespace bimrock
