// Load stepping (analysis/load_stepping.hpp) on stand-in structures whose answers are known by
// construction: a trial carries a step while the stage factor it reaches stays at or below a
// collapse factor F set by the test, and fails past it. The collapse bracket must hold F and be
// as narrow as the tolerance asks; parts carried must add up to the increment; a step that fails
// only numerically must never be taken for a collapse.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/load_stepping.hpp>

namespace bimrock {
namespace {

constexpr double kCollapse = 0.6137;  // F: the stand-in structure's collapse factor

// A stand-in structure: its state is the stage factor carried, and `answer` decides each trial.
struct Structure {
  double factor = 0.0;
  std::vector<double> tried{};        // the steps tried, in order
  std::vector<double> carried{};      // the factor after each carried part
  std::vector<Thoroughness> asked{};  // how thoroughly each trial was to be solved
  std::function<Trial(double from, double step)> answer{};

  SteppedIncrement step(double step, const SteppingOptions& options = {}) {
    const TryStep try_step = [&](double s, Thoroughness thoroughness) {
      tried.push_back(s);
      asked.push_back(thoroughness);
      return answer(factor, s);
    };
    const CarryStep carry = [&](const Trial& t) {
      factor = t.next.stage_factor;
      carried.push_back(factor);
    };
    return step_increment(step, factor, try_step, carry, options);
  }
};

Trial carried_to(double factor) {
  Trial t;
  t.status = Trial::Status::carried;
  t.next.stage_factor = factor;
  return t;
}

Trial collapsed(double proven_fraction = 1.0) {
  Trial t;
  t.status = Trial::Status::collapse;
  t.proven_fraction = proven_fraction;
  return t;
}

Trial failed() {
  return Trial{};  // Status::failed: no solution found, none proven absent
}

// Carries up to F, proves failure of any step beyond it (a proof of the whole step only).
Trial up_to_collapse(double from, double step) {
  return from + step <= kCollapse ? carried_to(from + step) : collapsed();
}

TEST(LoadStepping, CarriesAWholeIncrementBelowTheCollapse) {
  Structure s{.answer = up_to_collapse};
  const SteppedIncrement out = s.step(0.25);
  EXPECT_EQ(out.outcome, SteppedIncrement::Outcome::carried);
  EXPECT_DOUBLE_EQ(out.carried, 0.25);
  EXPECT_EQ(s.tried.size(), 1u);
}

TEST(LoadStepping, BracketsTheCollapseToTheTolerance) {
  Structure s{.answer = up_to_collapse};
  s.factor = 0.5;
  const SteppingOptions options{.bracket_tolerance = 1e-4};
  const SteppedIncrement out = s.step(0.25, options);
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_GT(out.failed, kCollapse);
  EXPECT_LE(out.failed - out.carried, options.bracket_tolerance * out.failed);
  EXPECT_DOUBLE_EQ(s.factor, out.carried);  // the state is the last part carried
  for (std::size_t i = 1; i < s.carried.size(); ++i)
    EXPECT_GT(s.carried[i], s.carried[i - 1]);
  EXPECT_FALSE(out.unstable_at_first_load);
  EXPECT_FALSE(out.undecided_inside);
}

TEST(LoadStepping, AimsAtACertificatesBoundAndNeedsFewerTrialsThanHalving) {
  // A certificate proves every step that reaches F (plus a hair): the bracket's upper end is F
  // at once, and the trials aim near it.
  Structure proving{.answer = [](double from, double step) {
    const double reach = from + step;
    if (reach <= kCollapse)
      return carried_to(reach);
    return collapsed((kCollapse * (1.0 + 1e-9) - from) / step);
  }};
  proving.factor = 0.5;
  const SteppedIncrement out = proving.step(0.25);
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_NEAR(out.failed, kCollapse, 1e-8);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_LE(out.failed - out.carried, 1e-4 * out.failed);

  Structure halving{.answer = up_to_collapse};
  halving.factor = 0.5;
  (void)halving.step(0.25);
  EXPECT_LT(proving.tried.size(), halving.tried.size());
}

TEST(LoadStepping, OnlyTheTrialsInsideAProvenBracketAreQuick) {
  // The first trial fails with a proof: every later one lies between a load carried and one
  // proven to fail, where an undecided answer moves neither end.
  Structure s{.answer = up_to_collapse};
  s.factor = 0.5;
  ASSERT_EQ(s.step(0.25).outcome, SteppedIncrement::Outcome::collapse);
  ASSERT_GE(s.asked.size(), 3u);
  EXPECT_EQ(s.asked.front(), Thoroughness::thorough);
  for (std::size_t i = 1; i < s.asked.size(); ++i)
    EXPECT_EQ(s.asked[i], Thoroughness::quick) << "trial " << i;

  // Without a proof, a failed trial bounds nothing: every cut is tried thoroughly.
  Structure unproven{.answer = [](double from, double step) {
    return step > 0.1 + 1e-15 ? failed() : up_to_collapse(from, step);
  }};
  (void)unproven.step(0.25);
  ASSERT_GE(unproven.asked.size(), 3u);
  for (const Thoroughness t : unproven.asked)
    EXPECT_EQ(t, Thoroughness::thorough);
}

TEST(LoadStepping, WhereOnlySmallStepsCarryThePartsGrowAndReachTheCollapse) {
  // Steps above 0.01 fail numerically (as near a limit load): from 0.5, the first part carried
  // is 0.25 / 32. Trying the whole rest again before each part would cost five bisections a
  // part, and the 40 allowed would end undecided at about 0.56. Parts that grow from the last
  // cost one each, and the increment reaches F, where the collapse is proven and bracketed.
  Structure s{.answer = [](double from, double step) {
    return step > 0.01 + 1e-15 ? failed() : up_to_collapse(from, step);
  }};
  s.factor = 0.5;
  const SteppedIncrement out = s.step(0.25);
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_GT(out.failed, kCollapse);
  EXPECT_LE(out.failed - out.carried, 1e-4 * out.failed);
  EXPECT_LE(s.tried.size(), 4u * 40u);
}

// Past F no step is solved, and none is proven to fail before it reaches U = kProvenAbove (as
// between the limit loads of non-associated flow and of associated flow): a step beyond U is
// proven to fail from U on, or from the fraction `least` of it where that is further up.
constexpr double kProvenAbove = 0.8;
Trial proven_above(double from, double step, double least = 0.0) {
  const double reach = from + step;
  if (reach <= kCollapse)
    return carried_to(reach);
  if (reach <= kProvenAbove)
    return failed();
  return collapsed(std::max((kProvenAbove - from) / step, least));
}

TEST(LoadStepping, CutsLeftUndecidedLookForAProofUpToTheStagesEnd) {
  const auto answer = [](double from, double step) { return proven_above(from, step); };
  Structure s{.answer = answer};
  s.factor = 0.5;
  const SteppedIncrement out = s.step(0.25, {.stage_end = 1.0});
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_TRUE(out.undecided_inside);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_GT(out.carried, 0.999 * kCollapse);  // the cuts' budget spent carrying towards F
  EXPECT_NEAR(out.failed, kProvenAbove, 1e-12);
  // The first trial for a proof goes to the stage's end.
  const auto first_proof = std::find(s.asked.begin(), s.asked.end(), Thoroughness::proof);
  ASSERT_NE(first_proof, s.asked.end());
  EXPECT_NEAR(s.tried[static_cast<std::size_t>(first_proof - s.asked.begin())], 1.0 - out.carried,
              1e-15);

  // Without the stage's end, the same cuts stop undecided.
  Structure alone{.answer = answer};
  alone.factor = 0.5;
  EXPECT_EQ(alone.step(0.25).outcome, SteppedIncrement::Outcome::undecided);
}

TEST(LoadStepping, WhereTheTrialToTheStagesEndIsUndecidedShorterOnesLookForTheProof) {
  // As above, but a trial past 0.95 is undecided too (its LCPs too large to decide): the trials
  // for a proof go half as far each, and the one that reaches 0.807 proves it from 0.8.
  Structure s{.answer = [](double from, double step) {
    return from + step > 0.95 ? failed() : proven_above(from, step);
  }};
  s.factor = 0.5;
  const SteppedIncrement out = s.step(0.25, {.stage_end = 1.0});
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_TRUE(out.undecided_inside);
  EXPECT_NEAR(out.failed, kProvenAbove, 1e-12);
  // The trials for a proof: to the stage's end, half as far (which proves it), and a quarter
  // (which does not: the search ends).
  std::vector<double> proofs;
  for (std::size_t k = 0; k < s.tried.size(); ++k)
    if (s.asked[k] == Thoroughness::proof)
      proofs.push_back(s.tried[k]);
  ASSERT_EQ(proofs.size(), 3u);
  EXPECT_NEAR(proofs[1], (1.0 - out.carried) / 2.0, 1e-15);
  EXPECT_NEAR(proofs[2], (1.0 - out.carried) / 4.0, 1e-15);
}

TEST(LoadStepping, AfterAProofShorterTrialsLookForANearerOne) {
  // As above, but a certificate proves a step to fail only from 90% of it on, or from U where
  // that is further down: the trial to the stage's end proves failure from 0.96 only, and the
  // one half as far from U.
  Structure s{.answer = [](double from, double step) { return proven_above(from, step, 0.9); }};
  s.factor = 0.5;
  const SteppedIncrement out = s.step(0.25, {.stage_end = 1.0});
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_TRUE(out.undecided_inside);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_NEAR(out.failed, kProvenAbove, 1e-12);
  EXPECT_EQ(s.asked.back(), Thoroughness::proof);
  EXPECT_NEAR(s.tried.back(), (1.0 - out.carried) / 4.0, 1e-15);  // it fails: the search ends
}

TEST(LoadStepping, ANumericalFailureIsCutAndTheRestCarriedNotTakenForACollapse) {
  // Steps longer than 0.1 fail numerically; everything below F carries.
  Structure s{.answer = [](double from, double step) {
    if (step > 0.1 + 1e-15)
      return failed();
    return up_to_collapse(from, step);
  }};
  const SteppedIncrement out = s.step(0.25);
  EXPECT_EQ(out.outcome, SteppedIncrement::Outcome::carried);
  EXPECT_NEAR(s.factor, 0.25, 1e-15);  // the parts add up to the increment
  EXPECT_GE(s.carried.size(), 3u);
}

TEST(LoadStepping, FailuresWithoutProofNearTheCollapseLeaveItUndecided) {
  Structure s{.answer = [](double from, double step) {
    return from + step <= kCollapse ? carried_to(from + step) : failed();
  }};
  s.factor = 0.5;
  const SteppedIncrement out = s.step(0.25);
  EXPECT_EQ(out.outcome, SteppedIncrement::Outcome::undecided);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_GT(out.carried, kCollapse * (1.0 - 1e-3));  // carried what could be
}

TEST(LoadStepping, CutToTheToleranceWithoutAProofTheShortestFailingStepIsSearchedOnceMore) {
  // Past F a step is decided only by an exhaustive search (as the complete method's proof,
  // which a longer budget reaches): the cuts reach the tolerance undecided, and the shortest
  // step that failed, searched so, is proven to fail. The bracket is then the tolerance's.
  Structure s;
  s.answer = [&s](double from, double step) {
    if (from + step <= kCollapse)
      return carried_to(from + step);
    return s.asked.back() == Thoroughness::exhaustive ? collapsed() : failed();
  };
  s.factor = 0.5;
  const SteppingOptions options{.bracket_tolerance = 1e-4};
  const SteppedIncrement out = s.step(0.25, options);
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_FALSE(out.undecided_inside);
  EXPECT_LE(out.carried, kCollapse);
  EXPECT_GT(out.failed, kCollapse);
  EXPECT_LE(out.failed - out.carried, options.bracket_tolerance * out.failed);
  EXPECT_EQ(std::count(s.asked.begin(), s.asked.end(), Thoroughness::exhaustive), 1);
  EXPECT_EQ(s.asked.back(), Thoroughness::exhaustive);

  // Where that search is undecided too, so is the increment: searched exhaustively once only.
  Structure never{.answer = [](double from, double step) {
    return from + step <= kCollapse ? carried_to(from + step) : failed();
  }};
  never.factor = 0.5;
  EXPECT_EQ(never.step(0.25, options).outcome, SteppedIncrement::Outcome::undecided);
  EXPECT_EQ(std::count(never.asked.begin(), never.asked.end(), Thoroughness::exhaustive), 1);

  // Nor is an LCP too large for that search to reach a proof searched so.
  Structure large{.answer = [](double from, double step) {
    if (from + step <= kCollapse)
      return carried_to(from + step);
    Trial t = failed();
    t.lcp_size = kRootOnlyRows + 1;
    return t;
  }};
  large.factor = 0.5;
  EXPECT_EQ(large.step(0.25, options).outcome, SteppedIncrement::Outcome::undecided);
  EXPECT_EQ(std::count(large.asked.begin(), large.asked.end(), Thoroughness::exhaustive), 0);
}

TEST(LoadStepping, NothingCarriedFromZeroTheStepBelowTheToleranceIsSearchedOnce) {
  // From a stage factor of 0 the relative tolerance is never reached: once the step that fails
  // is below the tolerance of the stage's load, it is searched exhaustively, once. Here that
  // search proves it (a structure unstable under its first load); the cuts stop there.
  const SteppingOptions options{.bracket_tolerance = 1e-4, .first_load = true};
  Structure s;
  s.answer = [&s](double, double) {
    return s.asked.back() == Thoroughness::exhaustive ? collapsed() : failed();
  };
  const SteppedIncrement out = s.step(0.25, options);
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_TRUE(out.unstable_at_first_load);
  EXPECT_LE(out.failed, options.bracket_tolerance);
  EXPECT_GT(out.failed, 0.5 * options.bracket_tolerance);  // the first step below it
  EXPECT_EQ(std::count(s.asked.begin(), s.asked.end(), Thoroughness::exhaustive), 1);
  // Where it decides nothing, the cuts go on as before, with no second such search.
  Structure never{.answer = [](double, double) { return failed(); }};
  EXPECT_EQ(never.step(0.25, options).outcome, SteppedIncrement::Outcome::undecided);
  EXPECT_EQ(std::count(never.asked.begin(), never.asked.end(), Thoroughness::exhaustive), 1);
  EXPECT_LT(never.asked.size(), 200u);
}

TEST(LoadStepping, AKinkSplitsTheStepAtTheKink) {
  // The first trial of the step reaches a softening law's kink at a quarter of it.
  Structure s{.answer = [](double from, double step) {
    Trial t = carried_to(from + step);
    if (from < 0.1 && from + step > 0.1 + 1e-12)
      t.kink = (0.1 - from) / step;
    return t;
  }};
  const SteppedIncrement out = s.step(0.4);
  EXPECT_EQ(out.outcome, SteppedIncrement::Outcome::carried);
  ASSERT_EQ(s.carried.size(), 2u);
  EXPECT_NEAR(s.carried[0], 0.1, 1e-15);
  EXPECT_NEAR(s.carried[1], 0.4, 1e-15);
}

TEST(LoadStepping, AFailureProvenAtTheFirstLoadIsAnInstabilityNotABracket) {
  // Every step fails, proven from a billionth of the load on.
  const auto unstable = [](double from, double step) { return collapsed((1e-9 - from) / step); };
  Structure first{.answer = unstable};
  const SteppedIncrement out = first.step(0.1, {.first_load = true});
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_TRUE(out.unstable_at_first_load);
  EXPECT_TRUE(first.carried.empty());
  EXPECT_EQ(first.tried.size(), 1u);  // no bisection towards zero load
  // Not the first load (something was carried before): the same failure is a bracket.
  Structure later{.answer = unstable};
  EXPECT_FALSE(later.step(0.1, {.first_load = false}).unstable_at_first_load);
}

TEST(LoadStepping, UndecidedTrialsBelowAProofLeaveTheBracketAsProvenAfterAFew) {
  // A structure whose collapse is proven only from 0.7 on (a bound above F), and whose trials
  // between F and 0.7 are undecided; those up to F carry. The bracket [carried, 0.7] holds F.
  Structure s{.answer = [](double from, double step) {
    if (from + step <= kCollapse)
      return carried_to(from + step);
    return from + step >= 0.7 ? collapsed((0.7 - from) / step) : failed();
  }};
  const SteppedIncrement out = s.step(1.0);
  ASSERT_EQ(out.outcome, SteppedIncrement::Outcome::collapse);
  EXPECT_NEAR(out.failed, 0.7, 1e-12);
  EXPECT_LE(out.carried, kCollapse);
  std::size_t undecided = 0;
  double at = 0.0;
  for (const double step : s.tried) {
    // Replays the trials: those that neither carried nor reached 0.7 were undecided.
    const double reached = at + step;
    if (reached <= kCollapse)
      at = reached;
    else if (reached < 0.7)
      ++undecided;
  }
  EXPECT_EQ(undecided, 3u);  // then the bracket stands: each costs a whole search
  EXPECT_TRUE(out.undecided_inside);
}

}  // namespace
}  // namespace bimrock
