// Verification: the two routes of the active-set method give the same analysis.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` (a jointed mass of 0.2 m blocks, Mohr-Coulomb joints with associated flow,
// a thrust on a strip loaded to collapse) is run once with every LCP solved on the dense
// active block (PlasticOptions::reduced_tangent_rows = -1) and once on the sparse reduced
// tangent wherever it applies (0): the carried stage factors, the monitor's displacement and the
// collapse bracket must agree, and the tangent must have run and proven collapse steps itself
// (a collapse proven on a tangent is a Farkas certificate checked with K, as the dense route's).
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/model/reference_cases.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

PlasticResult run_abutment(int reduced_tangent_rows) {
  PlasticOptions o;
  o.reduced_tangent_rows = reduced_tangent_rows;
  return run_plastic_analysis(build_model(abutment_case(100, 25, 1.2 * abutment_collapse_shear())),
                              o);
}

TEST(ReducedTangentRoute, GivesTheSameAnalysisAsTheDenseActiveBlock) {
  const PlasticResult dense = run_abutment(-1);
  const PlasticResult tangent = run_abutment(0);
  ASSERT_TRUE(dense.collapse.has_value());
  ASSERT_TRUE(tangent.collapse.has_value());
  int factorizations = 0;
  for (const IncrementRecord& r : tangent.history)
    factorizations += r.tangent_factorizations;
  for (const IncrementRecord& r : dense.history)
    EXPECT_EQ(r.tangent_factorizations, 0);
  EXPECT_GT(factorizations, 0) << "the tangent route never ran";
  std::printf(
      "collapse bracket: dense [%.6f, %.6f], tangent [%.6f, %.6f]; %d tangent factorizations\n",
      dense.collapse->carried, dense.collapse->failed, tangent.collapse->carried,
      tangent.collapse->failed, factorizations);
  // Both brackets hold the same collapse load: they overlap, each narrower than the tolerance
  // of the bisection (1e-4) plus one cut.
  EXPECT_NEAR(tangent.collapse->carried, dense.collapse->carried, 2e-4);
  EXPECT_NEAR(tangent.collapse->failed, dense.collapse->failed, 2e-4);
  // The increments before the first bisection are the same steps: same state after each.
  for (std::size_t i = 0; i < std::min(dense.history.size(), tangent.history.size()); ++i) {
    const IncrementRecord& a = dense.history[i];
    const IncrementRecord& b = tangent.history[i];
    if (a.stage_factor != b.stage_factor)
      break;  // the bisections may take other cuts
    const double u = a.monitors[0].norm();
    EXPECT_NEAR(b.monitors[0].x(), a.monitors[0].x(), 1e-7 * u) << "increment " << i;
    EXPECT_NEAR(b.monitors[0].y(), a.monitors[0].y(), 1e-7 * u) << "increment " << i;
  }
}

}  // namespace
}  // namespace bimrock
