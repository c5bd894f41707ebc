// Regression: the candidate rows of an increment change its cost, not its answer.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` (a jointed mass of 0.2 m blocks, Mohr-Coulomb joints with associated flow, a
// thrust on a strip loaded to collapse) is run with candidates only where the elastic predictor
// reaches yield (CandidateTuning::margin = 0) and with the default margin. Each
// increment's LCP has a unique solution (associated flow: a convex program with a positive
// definite elastic part), and rows that stay inactive do not change it: the carried stage
// factors, the monitor's displacement and the collapse bracket must agree. The margin is there
// to save candidate rounds: the margin run must not need more of them.
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

int total_rounds(const PlasticResult& r) {
  int rounds = 0;
  for (const IncrementRecord& h : r.history)
    rounds += h.rounds;
  return rounds;
}

TEST(CandidateMargin, ChangesTheRoundsNotTheAnalysis) {
  const PlasticResult exact = testing::run_abutment({.candidates = {.margin = 0.0}});
  const PlasticResult margin = testing::run_abutment({});
  std::printf("no margin, then margin: %d and %d candidate rounds\n", total_rounds(exact),
              total_rounds(margin));
  testing::expect_same_analysis(exact, margin);
  EXPECT_LT(total_rounds(margin), total_rounds(exact));
}

}  // namespace
}  // namespace bimrock
