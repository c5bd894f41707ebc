// Regression: the splitting of non-associated LCPs gives the analysis the block rule gives.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` with joints of no dilation (non-associated flow), loaded past its collapse, is
// run once with the non-associated LCPs on the reduced tangent solved by the block rule alone
// (SolverTuning::splitting = false, then the dense routes) and once split into associated ones
// whose active sets are tried on the LCP (the default): the carried stage factors, the monitor's
// displacement and the collapse bracket must agree, and the splitting must have solved some of
// the increments itself.
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

TEST(NonAssociatedSplitting, GivesTheSameAnalysisAsTheBlockRuleAlone) {
  const PlasticResult block_rule =
      testing::run_abutment({.solver = {.splitting = false}}, 100, {}, JointFlow::no_dilation);
  const PlasticResult split = testing::run_abutment({}, 100, {}, JointFlow::no_dilation);
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

}  // namespace
}  // namespace bimrock
