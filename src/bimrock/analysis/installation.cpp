#include <bimrock/analysis/installation.hpp>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/yield_modes.hpp>

namespace bimrock {

Eigen::VectorXd pretension_loads(const Model& model, const std::vector<YieldPoint>& points,
                                 const YieldPointIndex& index, const Presence& before,
                                 const Presence& now) {
  Eigen::VectorXd load = Eigen::VectorXd::Zero(model.n_dofs());
  for (std::size_t k = 0; k < model.bolt_springs.size(); ++k) {
    if (before.springs[k] || !now.springs[k])
      continue;
    const YieldPoint& p = points[static_cast<std::size_t>(index.spring_points[k])];
    const double t0 = bolt_of(model, p).pretension;
    if (t0 == 0.0)
      continue;
    const Eigen::VectorXd on_blocks =
        -p.weight * local_operator(model, p).e.transpose() * Eigen::Vector2d(t0, 0.0);
    load.segment<6>(6 * p.block_i) += on_blocks.head<6>();
    load.segment<6>(6 * p.block_j) += on_blocks.tail<6>();
  }
  return load;
}

void lock_off(const Model& model, const std::vector<YieldPoint>& points,
              const YieldPointIndex& index, const Presence& before, const Presence& now,
              AnalysisState& state) {
  for (std::size_t k = 0; k < model.bolt_springs.size(); ++k) {
    if (before.springs[k] || !now.springs[k])
      continue;
    const auto at = static_cast<std::size_t>(index.spring_points[k]);
    state.points[at] = PlasticState{};
    state.points[at].installed_at = local_strain(model, points[at], state.u);
  }
}

Eigen::VectorXd install_blocks(const Model& model, const YieldPointIndex& index, int st,
                               const Presence& now, AnalysisState& state) {
  const Stage& stage = model.stages[static_cast<std::size_t>(st)];
  Eigen::VectorXd placed = Eigen::VectorXd::Zero(model.n_dofs());
  if (stage.installed.empty())
    return placed;
  std::vector<char> added(model.blocks.size(), 0);
  for (const int b : stage.installed) {
    added[static_cast<std::size_t>(b)] = 1;
    if (const int p = index.block_points[static_cast<std::size_t>(b)]; p >= 0)
      state.points[static_cast<std::size_t>(p)] = PlasticState{};
  }
  for (int k = 0; k < model.n_interfaces(); ++k) {
    const Interface& f = model.interfaces[static_cast<std::size_t>(k)];
    const bool touches = added[static_cast<std::size_t>(f.block_i)] ||
                         (!f.is_support() && added[static_cast<std::size_t>(f.block_j)]);
    if (!touches || !now.block(f.block_i) || (!f.is_support() && !now.block(f.block_j)))
      continue;
    const InterfaceState at = interface_state(model, k, state.u);
    state.installed[k] = {at[0].delta, at[1].delta};
    for (std::size_t end = 0; end < 2; ++end) {
      if (const int p = index.interface_points[static_cast<std::size_t>(k)][end]; p >= 0) {
        state.points[static_cast<std::size_t>(p)] = PlasticState{};
        state.points[static_cast<std::size_t>(p)].installed_at = at[end].delta;
      }
    }
  }
  for (int k = 0; k < st; ++k) {
    const Eigen::VectorXd earlier =
        assemble_loads(model, model.stages[static_cast<std::size_t>(k)].loads);
    for (const int b : stage.installed)
      placed.segment<6>(6 * b) += earlier.segment<6>(6 * b);
  }
  return placed;
}

}  // namespace bimrock
