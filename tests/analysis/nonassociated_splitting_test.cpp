// Regression: the splitting of non-associated LCPs gives the analysis the block rule gives.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` with joints of no dilation (non-associated flow), loaded past its collapse, is
// run once with the non-associated LCPs on the reduced tangent solved by the block rule alone
// (SolverTuning::splitting = false, then the dense routes) and once split into associated ones
// whose active sets are tried on the LCP (the default): the carried stage factors, the monitor's
// displacement and the collapse bracket must agree, and the splitting must have solved some of
// the increments itself. The same for the dense active block tried first, for GMRES on the
// non-symmetric tangent against its LU, and for the splitting's Newton steps against none.
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

// One of an increment's counts of work, over the whole analysis.
int total(const PlasticResult& r, int IncrementRecord::*count) {
  int sum = 0;
  for (const IncrementRecord& i : r.history)
    sum += i.*count;
  return sum;
}

PlasticResult abutment_without_dilation(const PlasticTuning& tuning) {
  return testing::run_abutment(tuning, 100, {}, JointFlow::no_dilation);
}

TEST(NonAssociatedSplitting, GivesTheSameAnalysisAsTheBlockRuleAlone) {
  // Every LCP the reduced tangent serves goes to it (none to the dense block first).
  const PlasticResult block_rule =
      abutment_without_dilation({.solver = {.splitting = false, .dense_first_rows = 0}});
  const PlasticResult split = abutment_without_dilation({.solver = {.dense_first_rows = 0}});
  testing::expect_same_analysis(block_rule, split);
  // The splitting ran: its inner LCPs are active-set iterations on the symmetric tangent, far
  // more of them than the block rule alone takes.
  EXPECT_GT(total(split, &IncrementRecord::active_set_iterations),
            total(block_rule, &IncrementRecord::active_set_iterations));
}

// The dense active block first, where few rows are expected active (the default), against the
// reduced tangent for every LCP it serves: the same analysis, and the dense block solved some of
// the LCPs that would have gone to the tangent.
TEST(NonAssociatedSplitting, TheDenseBlockFirstGivesTheSameAnalysis) {
  const PlasticResult tangent = abutment_without_dilation({.solver = {.dense_first_rows = 0}});
  const PlasticResult dense_first = abutment_without_dilation({});
  testing::expect_same_analysis(tangent, dense_first);
  EXPECT_LT(total(dense_first, &IncrementRecord::tangent_factorizations),
            total(tangent, &IncrementRecord::tangent_factorizations));
}

// GMRES on the non-symmetric tangent, preconditioned by the associated form's factor (the
// default), against the LU alone: the same analysis, with fewer factorizations (the LU's and
// the preconditioner's Cholesky together).
TEST(NonAssociatedSplitting, GmresOnTheTangentGivesTheSameAnalysisAsTheLu) {
  const PlasticResult lu =
      abutment_without_dilation({.solver = {.iterative_tangent = false, .dense_first_rows = 0}});
  const PlasticResult gmres = abutment_without_dilation({.solver = {.dense_first_rows = 0}});
  testing::expect_same_analysis(lu, gmres);
  EXPECT_LT(total(gmres, &IncrementRecord::tangent_factorizations),
            total(lu, &IncrementRecord::tangent_factorizations));
}

// The splitting's Newton steps (the default) against proposals that are dropped where they fail:
// the same analysis, in fewer active-set iterations (157 against 166: the inner LCPs' steps and
// the proposals').
TEST(NonAssociatedSplitting, TheNewtonStepsGiveTheSameAnalysis) {
  const PlasticResult without =
      abutment_without_dilation({.solver = {.splitting_newton = false, .dense_first_rows = 0}});
  const PlasticResult newton = abutment_without_dilation({.solver = {.dense_first_rows = 0}});
  testing::expect_same_analysis(without, newton);
  EXPECT_LT(total(newton, &IncrementRecord::active_set_iterations),
            total(without, &IncrementRecord::active_set_iterations));
}

}  // namespace
}  // namespace bimrock
