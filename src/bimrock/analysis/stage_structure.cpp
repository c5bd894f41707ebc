#include <bimrock/analysis/stage_structure.hpp>

#include <utility>

#include <bimrock/analysis/support_check.hpp>

namespace bimrock {
StageStructure::StageStructure(const Model& model, const SolverTuning& tuning,
                               StiffnessFactorization factorization, Timings& timings)
    : model_(model), tuning_(tuning), factorization_(std::move(factorization)), timings_(timings) {}

void StageStructure::stand_on(const Presence& present) {
  if (k_ && present == present_)
    return;
  retire();
  solver_.reset();
  {
    ScopedTimer t(timings_, "assemble");
    lower_ = assemble_stiffness_lower(model_, present);
  }
  ScopedTimer f(timings_, "factorize");
  k_.reset();
  if (factorization_) {
    k_ = factorization_(present, lower_);
  } else {
    auto cholmod = std::make_unique<CholmodStiffnessFactor>(lower_);
    if (!cholmod->factorize())
      report_singular_stiffness(model_, cholmod->failed_column());
    k_ = std::move(cholmod);
  }
  present_ = present;
  solver_ = std::make_unique<IncrementSolver>(model_, *k_, lower_, tuning_);
  ++factorizations_;
}

void StageStructure::retire() {
  if (!solver_)
    return;
  const ZoneStatistics z = solver_->zone_statistics();
  retired_.condensations += z.condensations;
  retired_.reserve_switches += z.reserve_switches;
  retired_.regions += z.regions;
  retired_.tangent += z.tangent;
  retired_.condensed += z.condensed;
  retired_solve_seconds_ += k_->solver().work().solve_seconds;
}

ZoneStatistics StageStructure::zone_statistics() const {
  ZoneStatistics z = solver_->zone_statistics();
  z.condensations += retired_.condensations;
  z.reserve_switches += retired_.reserve_switches;
  z.regions += retired_.regions;
  z.tangent += retired_.tangent;
  z.condensed += retired_.condensed;
  return z;
}

double StageStructure::solve_seconds() const {
  return retired_solve_seconds_ + k_->solver().work().solve_seconds;
}

}  // namespace bimrock
