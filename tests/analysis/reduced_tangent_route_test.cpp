// Regression: the two routes of the active-set method give the same analysis.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` (a jointed mass of 0.2 m blocks, Mohr-Coulomb joints with associated flow,
// a thrust on a strip loaded to collapse) is run once with every LCP solved on the dense
// active block (SolverTuning::reduced_tangent_rows = -1) and once on the sparse reduced
// tangent wherever it applies (0): the carried stage factors, the monitor's displacement and the
// collapse bracket must agree, and the tangent must have run and proven collapse steps itself
// (a collapse proven on a tangent is a Farkas certificate checked with K, as the dense route's).
// The same when rounds are ended early by an iterate that shows their LCP lacks points, and
// when the LCPs on the tangent also hold every point around the plastic flow.
#include <algorithm>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

// Every LCP solved on the dense active block: the second method each test compares with.
const PlasticResult& dense_route() {
  static const PlasticResult result =
      testing::run_abutment({.solver = {.reduced_tangent_rows = -1}});
  return result;
}

int largest_lcp(const PlasticResult& r) {
  int largest = 0;
  for (const IncrementRecord& i : r.history)
    largest = std::max(largest, i.lcp_size);
  return largest;
}

TEST(ReducedTangentRoute, GivesTheSameAnalysisAsTheDenseActiveBlock) {
  const PlasticResult& dense = dense_route();
  const PlasticResult tangent = testing::run_abutment({.solver = {.reduced_tangent_rows = 0}});
  int factorizations = 0;
  for (const IncrementRecord& r : tangent.history)
    factorizations += r.tangent_factorizations;
  for (const IncrementRecord& r : dense.history)
    EXPECT_EQ(r.tangent_factorizations, 0);
  EXPECT_GT(factorizations, 0) << "the tangent route never ran";
  std::printf("dense route, then tangent route (%d tangent factorizations)\n", factorizations);
  testing::expect_same_analysis(dense, tangent);
}

TEST(ReducedTangentRoute, RoundsEndedByAnIterateGiveTheSameAnalysis) {
  // Every iterate of projected Newton on the tangent is checked on every point
  // (SolverTuning::interrupt_after = 1), and one that violates points outside its LCP ends
  // the round. That changes only which rounds run (the last round of every increment is solved
  // and checked whole), so the analysis must be the same as on the dense active block; and
  // rounds must have been ended so, or the test proves nothing. (Candidates around the flow
  // would leave too few points outside the LCPs of this small model: none.)
  const PlasticResult& dense = dense_route();
  const PlasticResult interrupted =
      testing::run_abutment({.candidates = {.near_rings = 0},
                             .solver = {.reduced_tangent_rows = 0, .interrupt_after = 1}});
  EXPECT_GT(interrupted.interrupted_rounds, 0) << "no round was ended by an iterate";
  EXPECT_EQ(dense.interrupted_rounds, 0);
  std::printf("%d rounds ended by an iterate\n", interrupted.interrupted_rounds);
  testing::expect_same_analysis(dense, interrupted);
}

TEST(ReducedTangentRoute, CandidatesAroundTheFlowGiveTheSameAnalysis) {
  // Where the last increment ran on the tangent, every point within CandidateTuning::near_rings
  // rings of the flow's blocks joins the LCP (inactive rows cost only their w there). More
  // candidates change only which rows each LCP holds, not its solution: the analysis must be
  // the dense route's, with and without them, and they must have made some LCP larger.
  const PlasticResult& dense = dense_route();
  const PlasticResult without = testing::run_abutment(
      {.candidates = {.near_rings = 0}, .solver = {.reduced_tangent_rows = 0}});
  const PlasticResult around = testing::run_abutment(
      {.candidates = {.near_rings = 2}, .solver = {.reduced_tangent_rows = 0}});
  const int largest_without = largest_lcp(without);
  const int largest_around = largest_lcp(around);
  EXPECT_GT(largest_around, largest_without) << "no LCP took the points around the flow";
  std::printf("largest LCP %d rows without them, %d with them\n", largest_without, largest_around);
  testing::expect_same_analysis(dense, without);
  testing::expect_same_analysis(dense, around);
}

TEST(ReducedTangentRoute, ARoundThatStallsOnThePointsAroundTheFlowGoesOnWithoutThem) {
  // Past the collapse the larger LCP has no solution, and projected Newton can lower its
  // objective step after step with no point outside the LCP violated. A round whose iterates,
  // shown to the interrupt from the first step on (SolverTuning::interrupt_after = 1), stall
  // so goes on without the points around the flow. On the 486-block abutment some rounds must
  // have done so, and the analysis must still be the dense route's.
  const PlasticResult dense = testing::run_abutment({.solver = {.reduced_tangent_rows = -1}}, 300);
  const PlasticResult stalled =
      testing::run_abutment({.candidates = {.near_rings = 2},
                             .solver = {.reduced_tangent_rows = 0, .interrupt_after = 1}},
                            300);
  EXPECT_GT(stalled.rounds_without_around, 0) << "no round stalled on the points around the flow";
  EXPECT_EQ(dense.rounds_without_around, 0);
  std::printf("%d rounds went on without the points around the flow\n",
              stalled.rounds_without_around);
  testing::expect_same_analysis(dense, stalled);
}

TEST(ReducedTangentRoute, ARoundLeftUnsolvedGoesOnWithoutThePointsAroundTheFlow) {
  // Iterates never shown to an interrupt (SolverTuning::interrupt_after = 0) and at most 3
  // iterations per LCP: rounds on the points around the flow reach the limit unsolved. Such a
  // round must go on without those points (the others fall back to the dense route and Lemke),
  // and the analysis must still be the dense route's.
  const PlasticResult& dense = dense_route();
  const PlasticResult unsolved = testing::run_abutment(
      {.candidates = {.near_rings = 2},
       .solver = {.active_set_iterations = 3, .reduced_tangent_rows = 0, .interrupt_after = 0}});
  EXPECT_GT(unsolved.rounds_without_around, 0) << "no unsolved round went on without them";
  std::printf("%d rounds went on without the points around the flow\n",
              unsolved.rounds_without_around);
  testing::expect_same_analysis(dense, unsolved);
}

}  // namespace
}  // namespace bimrock
