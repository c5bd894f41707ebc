// Regression: a step that fails without proving a collapse is cut, and the rest of its
// increment is tried again once a part has carried; the analysis goes on to the same collapse.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` is run with the default options and with at most two candidate rounds per
// trial (PlasticOptions::max_rounds = 2). From 0.44 on, most full increments of the limited run
// need more rounds than it allows: they fail numerically (no solution found, none disproven)
// and are cut. With associated flow the collapse load does not depend on the loading path (the
// bound theorems of limit analysis), so the limited run must reach the collapse bracket of the
// default run; up to its first cut it takes the same steps, with the same monitor displacement.
// After that the states differ by the path (the yield functions are linearized per step).
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

// The stage factor is a whole number of the load stage's increments (1/25 each).
bool on_an_increment(double factor) {
  const double n = factor * 25.0;
  return std::abs(n - std::round(n)) < 1e-9;
}

TEST(StepRetry, CarriesTheRestOfACutIncrementToTheSameCollapse) {
  const PlasticResult full = testing::run_abutment({});
  PlasticOptions limited;
  limited.max_rounds = 2;
  const PlasticResult cut = testing::run_abutment({}, 100, limited);
  ASSERT_FALSE(cut.stopped.has_value()) << cut.stopped->reason;
  testing::expect_same_analysis(full, cut);
  // The retry ran: a cut increment (between two whole ones) is followed by one that reaches
  // the end of its increment. Cutting alone only creeps towards the failed step's end.
  int retried = 0;
  for (std::size_t i = 1; i + 1 < cut.history.size(); ++i)
    if (cut.history[i].stage == 1 && !on_an_increment(cut.history[i].stage_factor) &&
        on_an_increment(cut.history[i + 1].stage_factor))
      ++retried;
  EXPECT_GT(retried, 0);
}

}  // namespace
}  // namespace bimrock
