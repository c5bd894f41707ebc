// The oracle of `bimrock bench --oracle`: an analysis that replays what its own trials ended
// with must be the same analysis, each increment in one candidate round, on one zone.
//
// Source of the expected numbers: a second method, the analysis that recorded the hints (the
// abutment model of `bimrock bench`, loaded to collapse): the same carried stage factors,
// monitor displacements and collapse bracket (support/same_analysis.hpp).
#include <stdexcept>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/analysis/trial_hints.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

TEST(TrialHints, ReplayingItsOwnRecordGivesTheSameAnalysisInOneRoundPerIncrement) {
  TrialHints hints;
  const PlasticResult recorded = testing::run_abutment({.hints = &hints});
  ASSERT_TRUE(recorded.collapse.has_value());
  ASSERT_GT(hints.trials.size(), recorded.history.size()) << "no failed trial was recorded";
  int rounds = 0, iterations = 0;
  for (const IncrementRecord& h : recorded.history) {
    rounds += h.rounds;
    iterations += h.active_set_iterations;
  }
  ASSERT_GT(rounds, static_cast<int>(recorded.history.size())) << "nothing for a replay to save";

  hints.mode = TrialHints::Mode::replay;
  const PlasticResult replayed = testing::run_abutment({.hints = &hints});
  testing::expect_same_analysis(recorded, replayed);
  ASSERT_EQ(replayed.history.size(), recorded.history.size());
  EXPECT_EQ(hints.next, hints.trials.size()) << "the replay did not make the same trials";
  int replayed_iterations = 0;
  for (const IncrementRecord& h : replayed.history) {
    EXPECT_EQ(h.rounds, 1) << "increment " << h.increment;
    replayed_iterations += h.active_set_iterations;
  }
  EXPECT_EQ(replayed.condensations, 1);
  EXPECT_LT(replayed_iterations, iterations);
  std::printf("rounds %d -> %zu, active-set iterations %d -> %d\n", rounds, replayed.history.size(),
              iterations, replayed_iterations);
}

TEST(TrialHints, HintsOfAnotherModelAreRefused) {
  TrialHints hints{TrialHints::Mode::replay, {{{1 << 30}, {}}}, 0};
  EXPECT_THROW((void)testing::run_abutment({.hints = &hints}), std::invalid_argument);
}

}  // namespace
}  // namespace bimrock
