#pragma once
/// @file The one boundary of the solution strategy: IncrementSolver takes a round's increment
/// LCP (increment_lcp.hpp) and returns its solution, a proof that it has none, or why it could
/// not decide. Behind it (docs/solution-strategy.md):
/// - the stiffness the LCP is solved on: K, or K condensed onto a zone (stiffness_zones.hpp);
/// - the primal-dual active-set method, warm-started, on the sparse reduced tangent when many
///   rows are active (Cholesky for associated flow; otherwise GMRES preconditioned by the
///   associated form's factor, else LU: a non-associated LCP is first split into associated
///   ones, whose active sets are tried on it, symmetric_splitting.hpp, unless the dense active
///   block solves it first where few rows are active), else on the dense active block (only the
///   columns of active rows are formed);
/// - a non-associated LCP that the dense active block leaves unsolved, split likewise, its
///   inner LCPs on the dense block;
/// - where it fails, Lemke on a working set of rows, then on the whole matrix;
/// - a non-associated LCP with exactly opposite flows (dilation 0): the solutions of the same
///   LCP with perturbed flows (IncrementLcp::perturbed), made exact on it;
/// - last, branch and bound on the complementary pairs, which decides every LCP.
#include <optional>
#include <vector>

#include <Eigen/Core>

#include <bimrock/model/model.hpp>
#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/branch_and_bound_lcp.hpp>
#include <bimrock/solve/increment_lcp.hpp>
#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/retry_schedule.hpp>
#include <bimrock/solve/stiffness_zones.hpp>

namespace bimrock {

/// Expert tuning of the solution strategy; the defaults are the method's, and no analysis needs
/// others (tests change them to compare routes).
struct SolverTuning {
  /// Solve each LCP by the active-set method first, Lemke only where it fails (false: Lemke
  /// always; the answers agree, only the time differs).
  bool active_set = true;
  /// The most iterations of the active-set method on one LCP: of the block rule, and again as
  /// many of projected Newton.
  int active_set_iterations = 50;
  /// The reduced tangent serves LCPs from this many rows expected active (the warm start's);
  /// below it the dense active block is cheaper. -1: never.
  int reduced_tangent_rows = 300;
  /// Where the tangent route fails, the dense routes take over on LCPs up to this many rows; a
  /// larger one is left undecided (Lemke is O(m^3), and the dense block needs a back-solve per
  /// active row).
  int dense_fallback_rows = 4000;
  /// On the reduced tangent, after this many steps of projected Newton each iterate is shown to
  /// the caller's interrupt (0: never).
  int interrupt_after = 3;
  /// A non-associated LCP on the reduced tangent is first split into associated ones, whose
  /// active sets are tried on it, and one that the dense active block leaves unsolved is split
  /// before the pivoting methods (symmetric_splitting.hpp); false: the block rule alone.
  bool splitting = true;
  /// The splitting on the reduced tangent takes Newton steps from the active sets it tries and
  /// that fail (symmetric_splitting.hpp); false: it drops them. (On the dense route it always
  /// takes them.)
  bool splitting_newton = true;
  /// The non-symmetric tangent of a non-associated LCP is first solved by GMRES preconditioned
  /// by the associated form's factor (unsymmetric_tangent.hpp); false: LU always.
  bool iterative_tangent = true;
  /// A non-symmetric LCP that the reduced tangent would serve, with fewer rows expected active
  /// than this, is tried on the dense active block first (the splitting solves tens of
  /// associated-form LCPs, the block's LU costs the cube of its rows). 0: never.
  int dense_first_rows = 750;
  /// After three tries of the dense active block first have failed in a row, it is tried only
  /// on every this-many-th LCP it would serve, until one succeeds (near a limit load it can fail
  /// on one LCP after another, each try costing its block's columns). 1: always.
  int dense_first_period = 4;
  ZoneTuning zones{};
};

struct IncrementSolution {
  enum class Outcome {
    solved,       ///< z solves the LCP (checked on its own conditions)
    no_solution,  ///< proven: no z exists (a certificate, or an exhausted complete search)
    interrupted,  ///< the caller's interrupt ended the solve, or it stalled (see solve())
    undecided     ///< neither solved nor proven unsolvable (round-off near a limit load)
  };
  Outcome outcome = Outcome::undecided;
  /// solved: the multipliers (an opening row's is its total gap); interrupted: the last iterate.
  Eigen::VectorXd z;
  /// no_solution, where a certificate was found: the mechanism's multipliers (>= 0, max 1).
  Eigen::VectorXd ray;
  /// no_solution under load control: the least fraction of the step the certificate proves to
  /// fail (1 without one).
  double proven_fraction = 1.0;
  bool on_tangent = false;  ///< the active-set method ran on the reduced tangent
  /// Routes::up_to_pivoting: undecided where the pivoting methods would start (Routes::pivoting
  /// goes on from there).
  bool pivoting_left = false;
  int active_set_iterations = 0;
  int tangent_factorizations = 0;
  int pivots = 0;                ///< Lemke's
  double columns_seconds = 0.0;  ///< of the time, forming columns K^-1 phi
};

/// How far a solve goes where its fast routes leave an LCP undecided. Thorough: on to the
/// block rule from the warm start, then the dense routes (the dense active block, Lemke, branch
/// and bound) up to SolverTuning::dense_fallback_rows rows. Quick: a non-associated LCP whose
/// splitting finds no solution ends there, and the dense routes take only LCPs of up to
/// reduced_tangent_rows rows, where they cost no more than the tangent route. Quick serves the
/// trials whose undecided answer bounds nothing: those inside a collapse bracket already proven.
/// Proof: a trial made only to find a proof that the step fails, solved as quick
/// (solve_increment() gives the associated proof the rounds it needs). Exhaustive: thorough,
/// and branch and bound searches kExhaustiveSearch times as long, on an LCP it left undecided
/// before too; for the shortest step that failed undecided, where the cuts end without a proof.
enum class Thoroughness { thorough, quick, proof, exhaustive };

/// How many times branch and bound's budget an exhaustive solve gives it. Near a limit load of
/// non-associated flow the shortest failing step's LCP is the smallest of the stage, and its
/// proof can take a few times the budget of a search made at every cut (measured: 4 300 - 5 100
/// nodes on 78 rows, where the budget allows about 4 000).
constexpr double kExhaustiveSearch = 4.0;

/// The largest LCP searched exhaustively. On 200 rows its budget pays for about 1 500 nodes
/// (n^3 / 3 each besides their pivots, BranchAndBoundOptions), and proofs of no solution take
/// thousands (3 000 - 5 100 measured on 60 - 78 rows); on larger LCPs the search ends undecided
/// all the same (a slope's factor-of-safety search on 670 - 740 rows took 19% longer for the
/// same answer).
constexpr int kExhaustiveRows = 200;

/// Above kExhaustiveRows, up to this many rows, an exhaustive solve is the root LP of branch and
/// bound alone, with a budget of its own (30 times a search's): for associated flow it decides
/// the LCP (a solution exists exactly where the LP is feasible), and where it is empty its
/// Farkas certificate proves any LCP unsolvable. Measured: a cohesionless slope's first
/// increment from rest, 1 134 rows on which Lemke ends on rays that certify nothing, proven
/// unsolvable in 402 pivots (0.6 s); feasible roots of 1 200 - 1 300 rows take 5 - 12 s, so it
/// is tried once an increment, not at every cut.
constexpr int kRootOnlyRows = 2000;

/// Which routes a solve takes: all of them, those before the pivoting methods (Lemke, branch
/// and bound; an LCP left undecided there is returned undecided), or the pivoting methods alone
/// (from the rows of the warm start). A caller with a cheaper proof of its own puts it between
/// the two.
enum class Routes { all, up_to_pivoting, pivoting };

class IncrementSolver {
 public:
  /// The iterate of the active-set method on the reduced tangent (z in the LCP's rows); true
  /// ends the solve.
  using Interrupt = ActiveSetLcp::Interrupt;

  /// `k` is K's factor (condensing onto regions and zones), `k_lower` its lower triangle; both
  /// must outlive this.
  IncrementSolver(const Model& model, StiffnessFactor& k, const SparseMatrix& k_lower,
                  const SolverTuning& tuning);

  /// Makes the LCPs hold every flagged block (per block of the model).
  void hold(const std::vector<char>& needed_blocks) { zones_.hold(needed_blocks); }
  /// Whether a yield point's rows can join the LCP at no extra cost (the zone covers it).
  [[nodiscard]] bool covers(const YieldPoint& point) const { return zones_.covers(point); }

  /// Solves a round's LCP; hold() must cover every block its rows touch. On the reduced tangent,
  /// `interrupt` sees the iterates, and with `stop_unsolved` an iterate that ends unsolved there
  /// (at the iteration limit, or where no step lowers the objective) is returned as interrupted
  /// instead of going on with the dense routes.
  [[nodiscard]] IncrementSolution solve(const IncrementLcp& lcp, const Interrupt* interrupt,
                                        bool stop_unsolved,
                                        Thoroughness thoroughness = Thoroughness::thorough,
                                        Routes routes = Routes::all);

  [[nodiscard]] const SolverTuning& tuning() const { return tuning_; }
  [[nodiscard]] ZoneStatistics zone_statistics() const { return zones_.statistics(); }
  /// The relative accuracy of the solves with K (solve_accuracy.hpp), measured once.
  [[nodiscard]] double k_accuracy() const;

 private:
  /// A non-associated LCP with exactly opposite flows that no route before branch and bound has
  /// solved: the LCPs of its rows perturbed by fractions from 1 (associated flow) down to 1e-4
  /// (IncrementLcp::perturbed), each solved quick by the routes before the pivoting methods from
  /// the last one's solution, and each solution made exact on this LCP (`dense`) by least-norm
  /// pivoting, or else its active set, opposite slips both active read as the point's opening,
  /// solved as a linear program. At dilation 0 the opposite slip columns of a joint point cancel:
  /// the block rule's active sets there are singular, and branch and bound's tree outgrows its
  /// budget, where the perturbed LCPs are solved as any other. Empty where none gives a solution;
  /// where associated flow is not solved, the rest are not tried (past its limit load none is).
  [[nodiscard]] std::optional<LcpResult> from_perturbed(const IncrementLcp& lcp,
                                                        const LcpProblem& dense,
                                                        IncrementSolution& out);

  SolverTuning tuning_;
  const SpdSolver& k_;
  const SparseMatrix& k_lower_;
  mutable std::optional<double> k_accuracy_;
  StiffnessZones zones_;
  ActiveSetLcp active_set_;
  ActiveSetLcp proposal_check_;  // tries the active sets the splitting proposes
  ActiveSetLcp after_newton_;    // the splitting's inner LCPs after a Newton step
  RetrySchedule dense_first_;    // of the dense active block first
  Lemke lemke_;
  BranchAndBoundLcp complete_;
  BranchAndBoundLcp exhaustive_;  // complete_ with kExhaustiveSearch times its budget
  BranchAndBoundLcp root_only_;   // the root LP alone, up to kRootOnlyRows rows
  // The last LCP that branch and bound left undecided, not searched again up to a scale of q:
  // the bisected first increment of a load on a stress-free state (q in proportion to the
  // step, the candidate rows the same) asks it again and again.
  std::optional<LcpProblem> undecided_;
};

}  // namespace bimrock
