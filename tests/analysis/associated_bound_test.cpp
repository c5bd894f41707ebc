// Radenkovic's first theorem as the proof of a non-associated collapse
// (analysis/associated_bound.hpp): where nothing else decides an increment of non-associated
// flow, associated flow's certificate, checked on the increment's own LCP, proves every load
// above the associated limit load. The routes are cut down to the reduced tangent alone, which
// decides the increments below the collapse and none past it, so that every proof comes from
// the associated flow.
//
// Expected numbers (statics of a block of weight W on a plane of slope theta with friction phi,
// no cohesion): pushed up the slope it slides at P = W (sin theta + cos theta tan phi), for
// every dilation, since nothing confines the block's lift. A joint of a wedge that dilation
// would have to lift against confinement makes the two limit loads differ; then the proof holds
// from the associated limit up, and the bracket is that wide.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/reference/reference_cases.hpp>

#include "support/degrees.hpp"
#include "support/incline_case.hpp"

namespace bimrock {
namespace {

PlasticTuning tangent_only() {
  PlasticTuning t;
  t.solver.reduced_tangent_rows = 0;
  t.solver.dense_fallback_rows = 0;
  return t;
}

TEST(AssociatedBound, ProvesTheNonAssociatedSlideOfABlockAtItsClosedForm) {
  testing::Incline in;
  in.dilation_deg = 0.0;
  const double t = in.slope_deg * testing::kDeg;
  const double up =
      in.weight() * (std::sin(t) + std::cos(t) * std::tan(in.friction_deg * testing::kDeg));
  const Vec2 push(-1.5 * up, 0.0);  // up the slope, 1.5 times the slide's force
  const Model model = build_model(testing::incline_case(in, push, 10));
  const PlasticResult r = run_plastic_analysis(model, {}, {}, tangent_only());
  ASSERT_TRUE(r.collapse.has_value()) << (r.stopped ? r.stopped->reason : std::string());
  EXPECT_FALSE(r.stopped.has_value());
  EXPECT_EQ(r.collapse->stage, 1);
  EXPECT_FALSE(r.collapse->mechanism.empty());
  EXPECT_LE(r.collapse->carried * push.norm(), up * (1.0 + 1e-6));
  EXPECT_GE(r.collapse->failed * push.norm(), up * (1.0 - 1e-6));
  EXPECT_LE(r.collapse->failed - r.collapse->carried,
            2.0 * PlasticOptions{}.bracket_tolerance * r.collapse->failed);
}

// The abutment of `bimrock bench` with joints of no dilation, its load raised in 50 steps: near
// 0.831 of the load no step is solved nor proven to fail, and the trial to the stage's end is
// what can still prove the collapse. Its first round holds the points of a step of 0.17; the
// associated increment solved on them violates points outside them, which the proof needs: a
// next round holds them, and the proof comes. Expected numbers (Radenkovic's first theorem): an
// associated certificate proves no load below the associated limit load, so the upper end of the
// bracket is not below the associated analysis's lower end (here, the same mechanism: its upper
// end), and no flow rule carries a load past that analysis's upper end.
TEST(AssociatedBound, TheTrialToTheStagesEndGetsThePointsItsProofNeeds) {
  const PlasticResult associated = run_plastic_analysis(
      build_model(abutment_case(100, 25, 1.2 * abutment_collapse_shear())), {}, {}, {});
  ASSERT_TRUE(associated.collapse.has_value());
  const PlasticResult r = run_plastic_analysis(
      build_model(abutment_case(100, 50, 1.2 * abutment_collapse_shear(), JointFlow::no_dilation)),
      {}, {}, {});
  ASSERT_FALSE(r.stopped.has_value()) << r.stopped->reason;
  ASSERT_TRUE(r.collapse.has_value());
  EXPECT_TRUE(r.collapse->undecided_inside);  // between the two limit loads
  EXPECT_FALSE(r.collapse->mechanism.empty());
  const double tolerance = PlasticOptions{}.bracket_tolerance;
  EXPECT_GE(r.collapse->failed, associated.collapse->carried);
  EXPECT_NEAR(r.collapse->failed, associated.collapse->failed,
              tolerance * associated.collapse->failed);
  EXPECT_LE(r.collapse->carried, associated.collapse->failed);
}

}  // namespace
}  // namespace bimrock
