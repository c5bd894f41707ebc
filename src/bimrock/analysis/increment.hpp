#pragma once
/// @file One load increment of the plastic analysis (eqs. 16-35): predict, select the candidate
/// rows, solve the increment's LCP, update, check every yield function; rounds until the check
/// finds no point violated outside the LCP.
#include <set>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/analysis_state.hpp>
#include <bimrock/analysis/candidates.hpp>
#include <bimrock/analysis/plastic_options.hpp>
#include <bimrock/analysis/timings.hpp>
#include <bimrock/assembly/plastic_state.hpp>
#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/assembly/yield_values.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/solve/increment_solver.hpp>
#include <bimrock/solve/spd_solver.hpp>

namespace bimrock {

/// What the increments of one stage share: the model, K's factor and the stage's load.
struct StageContext {
  const Model& model;
  const std::vector<YieldPoint>& points;
  const SpdSolver& k;
  const Stage& stage;
  const YieldEvaluator& yield;  // every yield function of every point, for the checks
  Eigen::VectorXd x_ref;        // K^-1 P_stage: displacement of the whole stage load, elastic
  Eigen::VectorXd control;      // displacement control: u_monitor . direction = control . U
  double control_rate = 0.0;    // control . x_ref
  Timings* timings = nullptr;   // phases of the increments: candidates, yield rows, LCP, check
  int control_block = -1;       // displacement control: the block the monitored point is on
  /// Under displacement control (the stage's, or one that follows a limit point): each step
  /// prescribes control . dU, and the load factor is found.
  [[nodiscard]] bool controlled() const { return control.size() > 0; }
};

/// What an increment hands on to the next: the warm start of its LCPs, and counters.
struct IncrementMemory {
  std::set<std::pair<int, int>> last_active;  // (point, mode) yielding in the last increment
  bool last_on_tangent = false;   // the last carried increment's LCP ran on the reduced tangent
  int interrupted_rounds = 0;     // rounds an iterate ended (SolverTuning::interrupt_after)
  int rounds_without_around = 0;  // rounds that went on without the points around the flow
};

/// What trying one increment ended with.
struct Trial {
  enum class Status { carried, collapse, failed };
  Status status = Status::failed;
  AnalysisState next;
  std::vector<YieldRow> rows;
  Eigen::VectorXd lambda;  // increments of the multipliers (opening: of the gap)
  Eigen::VectorXd du;
  Eigen::VectorXd ray;           // collapse: the mechanism's multipliers, where a certificate has
  double proven_fraction = 1.0;  // collapse: the least fraction of the step proven to fail
  double kink = 1.0;  // < 1: the fraction of the step at which a softening law reached its
                      // residual value (the step must stop there)
  int lcp_size = 0;
  int pivots = 0;
  int active_set_iterations = 0;
  int tangent_factorizations = 0;
  int rounds = 0;
};

/// One increment from state s: `step` is the increment of the stage factor (load control) or of
/// the prescribed displacement (displacement control).
/// `thoroughness`: how far its LCPs' solves go (Thoroughness).
Trial solve_increment(const StageContext& ctx, const AnalysisState& s, double step,
                      const PlasticOptions& options, const CandidateTuning& tuning,
                      IncrementSolver& solver, IncrementMemory& memory,
                      Thoroughness thoroughness = Thoroughness::thorough);

}  // namespace bimrock
