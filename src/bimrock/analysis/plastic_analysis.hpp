#pragma once
/// @file Elastoplastic and contact analysis by the Parametric Variational Principle (eqs. 16-35):
/// load stages split into increments, each increment one linear complementarity problem, the
/// elastic stiffness factorized once for the whole analysis, no equilibrium iterations.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <bimrock/analysis/analysis_state.hpp>
#include <bimrock/analysis/collapse.hpp>
#include <bimrock/analysis/factor_of_safety.hpp>
#include <bimrock/analysis/plastic_options.hpp>
#include <bimrock/analysis/timings.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

struct IncrementRecord {
  int stage = 0;
  /// 1-based within the stage, counting bisected steps; 0: the jacking of the pretension of bolts
  /// installed at the stage's start
  int increment = 0;
  double stage_factor = 0.0;   ///< after the increment
  std::vector<Vec2> monitors;  ///< monitor displacements after the increment [m]
  int yielding_points = 0;     ///< points with plastic flow in this increment
  int open_points = 0;         ///< interface points open after the increment
  int lcp_size = 0;
  int pivots = 0;                  ///< Lemke pivots (where the active-set method did not converge)
  int active_set_iterations = 0;   ///< solves of the active-set method (dense or tangent)
  int tangent_factorizations = 0;  ///< of them, on the sparse reduced tangent
  int rounds = 0;                  ///< LCP solves (candidate rounds) of the increment
  double seconds = 0.0;            ///< since the last record (failed trials included) [s]
};

/// The analysis stopped before the end of its stages without a proven collapse: an increment
/// could be neither carried nor shown to have no solution (round-off near a limit load).
struct Stop {
  int stage = 0;
  double factor = 0.0;  ///< the last carried stage factor
  std::string reason;
};

/// What the initial stress (model/initial_stress.hpp) balances before the first stage.
struct InitialStressCheck {
  double residual = 0.0;           ///< the largest entry of P_first_stage - f_internal [N]
  double relative_residual = 0.0;  ///< that over the largest entry of either
  int violated_points = 0;         ///< yield points outside their strength (allowed to yield)
};

struct PlasticResult {
  std::vector<YieldPoint> points;
  AnalysisState state;
  std::vector<IncrementRecord> history;
  std::optional<Collapse> collapse;
  std::optional<Stop> stopped;
  /// With PlasticOptions::factor_of_safety, after stages that carried: F by strength reduction.
  std::optional<FactorOfSafety> factor_of_safety;
  std::optional<InitialStressCheck> initial_stress;
  Timings timings;
  int stiffness_factorizations = 0;  ///< of K for the blocks present: 1 + stages that excavate
  /// Times K was condensed onto a zone (factorized again in another order; the last may be
  /// "no condensation"), times a zone outgrown was replaced by a reserve zone of the same
  /// factor, and the blocks of the last zone (stiffness_zones.hpp).
  int condensations = 0;
  int reserve_switches = 0;
  int regions = 0;             ///< times K was condensed onto a region (ZoneTuning::region_growth)
  int interrupted_rounds = 0;  ///< rounds an iterate ended (SolverTuning::interrupt_after)
  /// Rounds that stalled or ended unsolved on the points around the flow and went on without
  /// them (CandidateTuning::near_rings).
  int rounds_without_around = 0;
  int zone_blocks = 0;
  int tangent_factorizations = 0;  ///< of the LCPs' reduced tangents, over the whole analysis
};

/// Called after every carried increment (e.g. to write its results).
using IncrementCallback = std::function<void(const IncrementRecord&, const AnalysisState&)>;

/// Runs every stage of the model, then the factor of safety's search where the options ask for
/// it. Throws ModelError when the structure is not fully supported. A callback may throw to end
/// the analysis (a caller's interruption): everything it holds is released as it unwinds.
PlasticResult run_plastic_analysis(const Model& model, const PlasticOptions& options = {},
                                   const IncrementCallback& on_increment = {},
                                   const PlasticTuning& tuning = {},
                                   const FactorTrialCallback& on_factor_trial = {});

}  // namespace bimrock
