// Verification: the candidate rows of an increment change its cost, not its answer.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` (a jointed mass of 0.2 m blocks, Mohr-Coulomb joints with associated flow, a
// thrust on a strip loaded to collapse) is run with candidates only where the elastic predictor
// reaches yield (PlasticOptions::candidate_margin = 0) and with the default margin. Each
// increment's LCP has a unique solution (associated flow: a convex program with a positive
// definite elastic part), and rows that stay inactive do not change it: the carried stage
// factors, the monitor's displacement and the collapse bracket must agree. The margin is there
// to save candidate rounds: the margin run must not need more of them.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/model/reference_cases.hpp>

namespace bimrock {
namespace {

PlasticResult run_abutment(double margin) {
  PlasticOptions o;
  o.candidate_margin = margin;
  return run_plastic_analysis(build_model(abutment_case(100, 25, 1.2 * abutment_collapse_shear())),
                              o);
}

int total_rounds(const PlasticResult& r) {
  int rounds = 0;
  for (const IncrementRecord& h : r.history)
    rounds += h.rounds;
  return rounds;
}

TEST(CandidateMargin, ChangesTheRoundsNotTheAnalysis) {
  const PlasticResult exact = run_abutment(0.0);
  const PlasticResult margin = run_abutment(PlasticOptions{}.candidate_margin);
  ASSERT_TRUE(exact.collapse.has_value());
  ASSERT_TRUE(margin.collapse.has_value());
  std::printf("collapse bracket: no margin [%.6f, %.6f] in %d rounds, margin [%.6f, %.6f] in %d\n",
              exact.collapse->carried, exact.collapse->failed, total_rounds(exact),
              margin.collapse->carried, margin.collapse->failed, total_rounds(margin));
  // Both brackets hold the same collapse load: each narrower than the bisection's tolerance
  // (1e-4) plus one cut.
  EXPECT_NEAR(margin.collapse->carried, exact.collapse->carried, 2e-4);
  EXPECT_NEAR(margin.collapse->failed, exact.collapse->failed, 2e-4);
  for (std::size_t i = 0; i < std::min(exact.history.size(), margin.history.size()); ++i) {
    const IncrementRecord& a = exact.history[i];
    const IncrementRecord& b = margin.history[i];
    if (a.stage_factor != b.stage_factor)
      break;  // the bisections may take other cuts
    const double u = a.monitors[0].norm();
    EXPECT_NEAR(b.monitors[0].x(), a.monitors[0].x(), 1e-7 * u) << "increment " << i;
    EXPECT_NEAR(b.monitors[0].y(), a.monitors[0].y(), 1e-7 * u) << "increment " << i;
  }
  EXPECT_LT(total_rounds(margin), total_rounds(exact));
}

}  // namespace
}  // namespace bimrock
