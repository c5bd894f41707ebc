// The seconds each increment record reports (history.csv) are disjoint parts of the analysis:
// an increment that is carried in several parts (a bisection near the collapse, a softening
// kink) reports each part's own time, never the time of the parts before it again.
//
// Source of the expected bound: a conservation law. Disjoint intervals inside one call add up
// to no more than the call's wall-clock time.
#include <chrono>
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/reference/reference_cases.hpp>

namespace bimrock {
namespace {

TEST(IncrementSeconds, AddUpToNoMoreThanTheAnalysis) {
  // The abutment of `bimrock bench` (283 blocks), whose collapse is bracketed by bisection.
  const Model model = build_model(abutment_case(100, 25, 1.2 * abutment_collapse_shear()));
  const auto start = std::chrono::steady_clock::now();
  const PlasticResult r = run_plastic_analysis(model, {});
  const double wall =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(r.collapse.has_value());
  // The bisection carried parts of one increment: stage factors off the 1/25 grid.
  int parts = 0;
  double sum = 0.0;
  for (const IncrementRecord& h : r.history) {
    sum += h.seconds;
    const double on_grid = h.stage_factor * 25.0;
    if (h.stage > 0 && std::abs(on_grid - std::round(on_grid)) > 1e-9)
      ++parts;
  }
  ASSERT_GE(parts, 2) << "the test needs an increment carried in several parts";
  std::printf("%zu increments (%d parts of bisected ones): %.3f s of %.3f s\n", r.history.size(),
              parts, sum, wall);
  EXPECT_LE(sum, wall);
}

}  // namespace
}  // namespace bimrock
