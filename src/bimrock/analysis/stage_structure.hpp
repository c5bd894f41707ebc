#pragma once
/// @file What the increments of a stage stand on: K of the blocks and bolts present, its factor
/// and the increment solver on it. The analysis factorizes K once, and again only when what
/// stands changes (a stage excavates, or installs bolts); a model without either keeps its first
/// factor.
#include <memory>
#include <vector>

#include <bimrock/analysis/timings.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/model/presence.hpp>
#include <bimrock/solve/increment_solver.hpp>
#include <bimrock/solve/stiffness_factor.hpp>

namespace bimrock {

class StageStructure {
 public:
  /// K is factorized by `factorization` (empty: by CHOLMOD in this process).
  StageStructure(const Model& model, const SolverTuning& tuning,
                 StiffnessFactorization factorization, Timings& timings);

  /// Makes K that of what is `present`, assembled and factorized anew if it differs from the
  /// last. Throws ModelError naming a block left free.
  void stand_on(const Presence& present);

  [[nodiscard]] const Presence& present() const { return present_; }
  [[nodiscard]] const SpdSolver& k() const { return k_->solver(); }
  [[nodiscard]] IncrementSolver& solver() { return *solver_; }
  /// Factorizations of K for what stands (1 without excavation or bolts).
  [[nodiscard]] int factorizations() const { return factorizations_; }
  /// The solves and zones of every factor so far (stiffness_zones.hpp, summed).
  [[nodiscard]] ZoneStatistics zone_statistics() const;
  [[nodiscard]] double solve_seconds() const;

 private:
  void retire();  // adds the statistics of the factor in use to those kept

  const Model& model_;
  SolverTuning tuning_;
  StiffnessFactorization factorization_;
  Timings& timings_;
  Presence present_;
  SparseMatrix lower_;
  std::unique_ptr<StiffnessFactor> k_;
  std::unique_ptr<IncrementSolver> solver_;
  int factorizations_ = 0;
  ZoneStatistics retired_;
  double retired_solve_seconds_ = 0.0;
};

}  // namespace bimrock
