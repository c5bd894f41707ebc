#pragma once
/// @file Elastoplastic and contact analysis by the Parametric Variational Principle (eqs. 16-35):
/// load stages split into increments, each increment one linear complementarity problem, the
/// elastic stiffness factorized once for the whole analysis, no equilibrium iterations.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <bimrock/analysis/timings.hpp>
#include <bimrock/analysis/trial_hints.hpp>
#include <bimrock/assembly/yield_system.hpp>

namespace bimrock {

struct PlasticOptions {
  /// A failed increment is bisected until the collapse bracket is this narrow (relative).
  double bracket_tolerance = 1e-4;
  int max_bisections = 40;
  /// Rounds of "solve, check every yield function, add the violated ones" per increment.
  int max_rounds = 30;
  /// A yield function counts as violated above this fraction of the stress scale.
  double yield_tolerance = 1e-9;
  /// A point's rows are candidates of the increment's LCP where its elastic predictor f + df
  /// reaches yield, or comes within margin |df| of it (0: only where it reaches yield), the
  /// nearest first and at most two such points per point that reaches yield. Plastic flow moves
  /// stress onto points the predictor left below yield; as candidates from the start they cost
  /// a row each, where they would otherwise cost a further round (LCP, update, check of every
  /// point). 3 was measured on the abutment model of `bimrock bench` (979 blocks: candidate
  /// rounds 92 -> 71, tangent factorizations 267 -> 143; 10 saved no more). A round that
  /// adds violated points also adds, at most two per violated point, the points whose change
  /// beyond the predictor's (the round's plastic flow), margin times over, reaches yield
  /// (10^4 blocks: rounds of the increments from 0.60 to the collapse 31 -> 24).
  double candidate_margin = 3.0;
  /// Where the last increment's LCP ran on the reduced tangent, every point within this many
  /// rings of neighbours of the plastic flow's blocks (the last increment's active rows and
  /// the step's required points) is a candidate too: there a row that stays inactive costs only
  /// its share of w, and the flow spreads to the next blocks (10^4 blocks: rounds
  /// 52 -> 32 and the whole analysis 6-7% faster with 2; 0: none).
  int near_rings = 2;
  /// The most iterations of the active-set method on one LCP: of the block rule, and again as
  /// many of projected Newton (a round that reaches it falls back to the dense route and Lemke).
  int active_set_iterations = 50;
  /// Solve each LCP by the primal-dual active-set method first, Lemke only where it fails
  /// (false: Lemke always; the answers agree, only the time differs).
  bool active_set = true;
  /// The active-set method solves the equations of each active set on the sparse reduced
  /// tangent (one factorization of K's size per iteration) instead of the dense active block
  /// when the increment's LCP is symmetric and at least this many rows are expected active (the
  /// last increment's and the open joints'); below it the dense block is cheaper. -1: never.
  int reduced_tangent_rows = 300;
  /// Where the tangent route fails (no convergence, a tangent that is neither positive definite
  /// nor a proven mechanism), the dense active block and Lemke take over on LCPs up to this
  /// many rows; a larger LCP fails the step, which is then cut (Lemke is O(m^3) and the dense
  /// block needs a back-solve per active row: hours at 10^4 rows).
  int dense_fallback_rows = 4000;
  /// On the reduced tangent, after this many steps of projected Newton on a round's LCP, each
  /// iterate is checked on every point, and one that violates points outside the LCP ends the
  /// round: the next round holds them (0: never); so does the last iterate where no step lowers
  /// the objective, before the round would fail. Near a collapse the LCP of a round that
  /// lacks the mechanism's points can take projected Newton many damped steps, where the
  /// round that holds them proves the collapse at once (10^4 blocks: the step past the collapse
  /// 1.2 -> 0.8 s, the whole analysis 6.65 -> 6.29 s, medians of 3). 3 since the candidates
  /// around the flow (10^4 blocks: 4.0-4.2 s against 4.4-4.5 s with 8, 4.3-4.4 s
  /// with 2, 20 s with 1; 10^5 blocks about the same; 979 blocks 0.82 s against 0.71 s).
  int interrupt_after = 3;
  /// The LCPs are solved on K condensed statically onto a zone of blocks that holds every
  /// candidate point (docs/formulation.md) while that zone is at most this fraction of the
  /// model; a larger one is not worth it, and the analysis goes on with K itself (0: never
  /// condense, 1: always). The zone has at least least_zone_blocks blocks.
  double condensed_zone_fraction = 0.5;
  int least_zone_blocks = 200;
  /// K is condensed only once the required candidates of a round touch more than this many
  /// blocks: before, the LCPs are solved on K itself, whose few columns K^-1 phi cost less
  /// than factorizing K in a new order (0: condense from the first LCP).
  int condense_after_blocks = 16;
  /// K's order for a zone also makes room for this many reserve zones around it (nested, each
  /// rings of blocks larger): a zone outgrown is replaced by a reserve that holds what is
  /// needed without factorizing K again (0: none).
  int zone_reserves = 2;
  /// Zones are condensed in two steps where it pays: K onto a region of this many times the
  /// zone's blocks (at least twice the last region; within condensed_zone_fraction of the
  /// model), then the region's S onto the zone. A zone outgrown inside its region costs a
  /// factorization of the region's S instead of K's (0: no regions, zones condensed from K).
  double region_growth = 4.0;
  /// A region has at most this fraction of the model's blocks: a larger one costs a good part
  /// of K's factorization at each zone condensed from it, and its factor adds to the peak
  /// memory (at 10^4 blocks, regions of a third of the model saved no time and took the memory
  /// from 1.66 to 1.96 times the limit's).
  double region_fraction = 0.25;
  /// Record each phase's peak resident memory in the timings (benchmarks).
  bool track_memory = false;
  /// Record each trial's last LCP and active rows here, or replay a record of the same model
  /// (trial_hints.hpp: the oracle of `bimrock bench --oracle`; null: neither).
  TrialHints* hints = nullptr;
};

/// The state the analysis carries from increment to increment.
struct AnalysisState {
  Eigen::VectorXd u;                 ///< total block unknowns
  std::vector<PlasticState> points;  ///< per yield point
  double stage_factor = 0.0;         ///< fraction of the current stage's loads applied
};

struct IncrementRecord {
  int stage = 0;
  int increment = 0;           ///< 1-based within the stage, counting bisected steps
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

/// One active yield mode of a collapse mechanism.
struct MechanismEntry {
  int point = 0;
  int mode = 0;
  double multiplier = 0.0;  ///< normalized to the largest
};

/// The structure could not carry a load increment: the collapse load lies in
/// [carried, failed] (stage factors) and the mechanism is that of the last carried step.
struct Collapse {
  int stage = 0;
  double carried = 0.0;
  double failed = 0.0;
  std::vector<MechanismEntry> mechanism;
  Eigen::VectorXd direction;  ///< displacement increment of the last carried step, unit norm
  /// Nothing of the first stage could be carried: the structure is proven to fail under a
  /// fraction of its first load no larger than the bracket tolerance (e.g. a cohesionless arch
  /// thinner than its least thickness under its own weight). `failed` is that fraction.
  bool unstable_at_first_load = false;
};

/// The analysis stopped before the end of its stages without a proven collapse: an increment
/// could be neither carried nor shown to have no solution (round-off near a limit load).
struct Stop {
  int stage = 0;
  double factor = 0.0;  ///< the last carried stage factor
  std::string reason;
};

struct PlasticResult {
  std::vector<YieldPoint> points;
  AnalysisState state;
  std::vector<IncrementRecord> history;
  std::optional<Collapse> collapse;
  std::optional<Stop> stopped;
  Timings timings;
  /// Times K was condensed onto a zone (factorized again in another order; the last may be
  /// "no condensation"), times a zone outgrown was replaced by a reserve zone of the same
  /// factor, and the blocks of the last zone (docs/formulation.md).
  int condensations = 0;
  int reserve_switches = 0;
  int regions = 0;  ///< times K was condensed onto a region (PlasticOptions::region_growth)
  int interrupted_rounds = 0;  ///< rounds an iterate ended (PlasticOptions::interrupt_after)
  /// Rounds that stalled or ended unsolved on the points around the flow and went on without
  /// them (PlasticOptions::near_rings).
  int rounds_without_around = 0;
  int zone_blocks = 0;
};

/// Called after every carried increment (e.g. to write its results).
using IncrementCallback = std::function<void(const IncrementRecord&, const AnalysisState&)>;

/// Runs every stage of the model. Throws ModelError when the structure is not fully supported.
PlasticResult run_plastic_analysis(const Model& model, const PlasticOptions& options = {},
                                   const IncrementCallback& on_increment = {});

}  // namespace bimrock
