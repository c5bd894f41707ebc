#pragma once
/// @file What the increments of a stage stand on: K of the blocks present, its factor and the
/// increment solver on it. The analysis factorizes K once, and again only after a stage that
/// excavates (the blocks present change); a model without excavation keeps its first factor.
#include <memory>
#include <vector>

#include <bimrock/analysis/timings.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/solve/increment_solver.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {

class StageStructure {
 public:
  StageStructure(const Model& model, const SolverTuning& tuning, Timings& timings);

  /// Makes K that of the blocks flagged in `present` (per block), assembled and factorized anew
  /// if they differ from the last ones. Throws ModelError naming a block left free.
  void stand_on(const std::vector<char>& present);

  [[nodiscard]] const std::vector<char>& present() const { return present_; }
  [[nodiscard]] SparseCholesky& k() { return *k_; }
  [[nodiscard]] IncrementSolver& solver() { return *solver_; }
  /// Factorizations of K for the blocks present (1 without excavation).
  [[nodiscard]] int factorizations() const { return factorizations_; }
  /// The solves and zones of every factor so far (stiffness_zones.hpp, summed).
  [[nodiscard]] ZoneStatistics zone_statistics() const;
  [[nodiscard]] double solve_seconds() const;

 private:
  void retire();  // adds the statistics of the factor in use to those kept

  const Model& model_;
  SolverTuning tuning_;
  Timings& timings_;
  std::vector<char> present_;
  SparseMatrix lower_;
  std::unique_ptr<SparseCholesky> k_;
  std::unique_ptr<IncrementSolver> solver_;
  int factorizations_ = 0;
  ZoneStatistics retired_;
  double retired_solve_seconds_ = 0.0;
};

}  // namespace bimrock
