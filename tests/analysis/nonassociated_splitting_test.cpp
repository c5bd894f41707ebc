// Regression: the splitting of non-associated LCPs gives the analysis the block rule gives.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` with joints of no dilation (non-associated flow), loaded past its collapse, is
// run once with the non-associated LCPs on the reduced tangent solved by the block rule alone
// (SolverTuning::splitting = false, then the dense routes) and once split into associated ones
// whose active sets are tried on the LCP (the default): the carried stage factors, the monitor's
// displacement and the collapse bracket must agree, and the splitting must have solved some of
// the increments itself. The same for the dense active block tried first.
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

TEST(NonAssociatedSplitting, GivesTheSameAnalysisAsTheBlockRuleAlone) {
  // Every LCP the reduced tangent serves goes to it (none to the dense block first).
  const PlasticResult block_rule = testing::run_abutment(
      {.solver = {.splitting = false, .dense_first_rows = 0}}, 100, {}, JointFlow::no_dilation);
  const PlasticResult split =
      testing::run_abutment({.solver = {.dense_first_rows = 0}}, 100, {}, JointFlow::no_dilation);
  testing::expect_same_analysis(block_rule, split);
  // The splitting ran: its inner LCPs are active-set iterations on the symmetric tangent, far
  // more of them than the block rule alone takes.
  int alone = 0, with_splitting = 0;
  for (const IncrementRecord& i : block_rule.history)
    alone += i.active_set_iterations;
  for (const IncrementRecord& i : split.history)
    with_splitting += i.active_set_iterations;
  EXPECT_GT(with_splitting, alone);
}

// The dense active block first, where few rows are expected active (the default), against the
// reduced tangent for every LCP it serves: the same analysis, and the dense block solved some of
// the LCPs that would have gone to the tangent.
TEST(NonAssociatedSplitting, TheDenseBlockFirstGivesTheSameAnalysis) {
  const PlasticResult tangent =
      testing::run_abutment({.solver = {.dense_first_rows = 0}}, 100, {}, JointFlow::no_dilation);
  const PlasticResult dense_first = testing::run_abutment({}, 100, {}, JointFlow::no_dilation);
  testing::expect_same_analysis(tangent, dense_first);
  int on_tangent = 0, with_dense_first = 0;
  for (const IncrementRecord& i : tangent.history)
    on_tangent += i.tangent_factorizations;
  for (const IncrementRecord& i : dense_first.history)
    with_dense_first += i.tangent_factorizations;
  EXPECT_LT(with_dense_first, on_tangent);
}

}  // namespace
}  // namespace bimrock
