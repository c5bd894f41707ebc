// The console line of the factor of safety says what the search found, and why it ended where
// it did: each outcome of FactorOfSafety (written by hand here) gets its own statement.
#include <string>

#include <gtest/gtest.h>

#include <bimrock/io/factor_of_safety_text.hpp>

namespace bimrock {
namespace {

bool says(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

FactorOfSafety bracketed(double lower, double upper, bool undecided) {
  FactorOfSafety f;
  f.lower = lower;
  f.undecided = undecided;
  Collapse c;
  c.carried = lower;
  c.failed = upper;
  f.collapse = c;
  return f;
}

TEST(FactorOfSafetyText, ABracketGivesBothEnds) {
  const std::string t = factor_of_safety_text(bracketed(1.35, 1.3513, false));
  EXPECT_TRUE(says(t, "F between 1.3500 (carried) and 1.3513 (fails)")) << t;
  EXPECT_FALSE(says(t, "could not be solved")) << t;
}

TEST(FactorOfSafetyText, ABracketThatAnUndecidedTrialEndedSaysItIsWiderThanItsTolerance) {
  const std::string t = factor_of_safety_text(bracketed(0.6, 0.7, true));
  EXPECT_TRUE(says(t, "F between 0.6000 (carried) and 0.7000 (fails)")) << t;
  EXPECT_TRUE(says(t, "wider than its tolerance")) << t;
}

TEST(FactorOfSafetyText, BelowOneWithNothingCarriedSaysWhyTheSearchEnded) {
  // Every F down to 1 / largest failed.
  const std::string all_failed = factor_of_safety_text(bracketed(0.0, 0.1, false));
  EXPECT_TRUE(says(all_failed, "F < 0.1000")) << all_failed;
  EXPECT_TRUE(says(all_failed, "factor_of_safety.largest")) << all_failed;
  // F = 0.7 failed, and the trial below it was undecided: the search never reached the largest
  // strengths, so the line must not say it did.
  const std::string ended = factor_of_safety_text(bracketed(0.0, 0.7, true));
  EXPECT_TRUE(says(ended, "F < 0.7000")) << ended;
  EXPECT_TRUE(says(ended, "could not be solved accurately, nor shown to fail")) << ended;
  EXPECT_FALSE(says(ended, "factor_of_safety.largest")) << ended;
}

TEST(FactorOfSafetyText, WithoutAProvenFailureItIsALowerBound) {
  FactorOfSafety undecided;
  undecided.lower = 2.15;
  undecided.undecided = true;
  const std::string u = factor_of_safety_text(undecided);
  EXPECT_TRUE(says(u, "F >= 2.1500; the next step could not be solved")) << u;
  FactorOfSafety largest;
  largest.lower = 10.0;
  const std::string l = factor_of_safety_text(largest);
  EXPECT_TRUE(says(l, "F >= 10.0000, the largest tried")) << l;
}

}  // namespace
}  // namespace bimrock
