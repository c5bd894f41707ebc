// The schedule of a route that may fail (the dense active block first). Expected answers are
// the rule itself, counted by hand: every chance is taken until three tries in a row fail, then
// every fourth, until one succeeds.
#include <gtest/gtest.h>

#include <bimrock/solve/retry_schedule.hpp>

namespace bimrock {
namespace {

TEST(RetrySchedule, TriesEveryPeriodthChanceAfterFailuresInARowUntilOneSucceeds) {
  RetrySchedule schedule(3, 4);
  // Two failures, a success, then three failures: all six tried.
  for (const bool succeeds : {false, false, true, false, false, false}) {
    ASSERT_TRUE(schedule.try_now());
    schedule.tried(succeeds);
  }
  // Now chances 1-3 are passed by, the 4th is tried (and fails), and again.
  for (int round = 0; round < 2; ++round) {
    for (int chance = 1; chance <= 3; ++chance)
      EXPECT_FALSE(schedule.try_now()) << round << " " << chance;
    ASSERT_TRUE(schedule.try_now());
    schedule.tried(false);
  }
  for (int chance = 1; chance <= 3; ++chance)
    EXPECT_FALSE(schedule.try_now());
  ASSERT_TRUE(schedule.try_now());
  schedule.tried(true);  // a success: every chance again
  for (int chance = 0; chance < 5; ++chance)
    EXPECT_TRUE(schedule.try_now());
}

TEST(RetrySchedule, APeriodOfOneTriesAlways) {
  RetrySchedule schedule(1, 1);
  for (int chance = 0; chance < 10; ++chance) {
    ASSERT_TRUE(schedule.try_now());
    schedule.tried(false);
  }
}

}  // namespace
}  // namespace bimrock
