#pragma once
// What the regression tests share that run one plastic analysis two ways (another route):
// the model, and the check that both runs give the same collapse bracket and, up to the first
// step the bisections cut differently, the same monitor displacements.
#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/reference/reference_cases.hpp>

namespace bimrock::testing {

/// The abutment model of `bimrock bench` asked for `blocks` blocks (100 gives 283: the mass is at
/// least 8 m wide; 300 gives 486), loaded to collapse: a jointed mass, Mohr-Coulomb joints with
/// associated flow (or none of dilation), a thrust on a strip.
inline PlasticResult run_abutment(const PlasticTuning& tuning, int blocks = 100,
                                  const PlasticOptions& options = {},
                                  JointFlow flow = JointFlow::associated) {
  return run_plastic_analysis(
      build_model(abutment_case(blocks, 25, 1.2 * abutment_collapse_shear(), flow)), options, {},
      tuning);
}

inline void expect_same_analysis(const PlasticResult& a, const PlasticResult& b) {
  ASSERT_TRUE(a.collapse.has_value());
  ASSERT_TRUE(b.collapse.has_value());
  std::printf("collapse brackets: [%.6f, %.6f] and [%.6f, %.6f]\n", a.collapse->carried,
              a.collapse->failed, b.collapse->carried, b.collapse->failed);
  // Both brackets hold the same collapse load: they overlap, each narrower than the tolerance
  // of the bisection (1e-4) plus one cut.
  EXPECT_NEAR(b.collapse->carried, a.collapse->carried, 2e-4);
  EXPECT_NEAR(b.collapse->failed, a.collapse->failed, 2e-4);
  EXPECT_LE(a.collapse->carried, b.collapse->failed);
  EXPECT_LE(b.collapse->carried, a.collapse->failed);
  // The increments before the first bisection are the same steps: same state after each.
  for (std::size_t i = 0; i < std::min(a.history.size(), b.history.size()); ++i) {
    const IncrementRecord& x = a.history[i];
    const IncrementRecord& y = b.history[i];
    if (x.stage_factor != y.stage_factor)
      break;  // the bisections may take other cuts
    const double u = x.monitors[0].norm();
    EXPECT_NEAR(y.monitors[0].x(), x.monitors[0].x(), 1e-7 * u) << "increment " << i;
    EXPECT_NEAR(y.monitors[0].y(), x.monitors[0].y(), 1e-7 * u) << "increment " << i;
  }
}

}  // namespace bimrock::testing
