// The paper's example 2 (pull-out of a half-brick, Zhang & Lu) with cohesive and frictional
// joints: whatever the dilation, from 0 to the friction angle, the analysis ends with a proven
// collapse (a bracket and a mechanism), never stopped, within Radenkovic's bounds (associated
// analyses of this code, so a consistency test rather than a verification). The complete LCP
// method decides every increment of non-associated flow, including the degenerate ones of
// dilation 0 (opposite slip flows) on which Lemke's method ends on rays that prove nothing.
#include <cmath>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/pull_out_case.hpp"

namespace bimrock {
namespace {

CaseSpec pull_out_case(double friction_deg, double dilation_deg) {
  JointStrength s;
  s.cohesion = Softening::constant(20e3);
  s.friction = Softening::constant(std::tan(friction_deg * M_PI / 180.0));
  s.dilation = std::tan(dilation_deg * M_PI / 180.0);
  return testing::pull_out_case(s, 120e3, 30);
}

// The collapse load factor's bracket of the pull-out with friction phi and dilation psi.
Collapse pull_out_collapse(double phi, double psi) {
  const PlasticResult r = run_plastic_analysis(build_model(pull_out_case(phi, psi)));
  EXPECT_TRUE(r.collapse.has_value()) << "phi " << phi << ", psi " << psi;
  EXPECT_FALSE(r.stopped.has_value()) << "phi " << phi << ", psi " << psi;
  return r.collapse.value_or(Collapse{});
}

// Radenkovic's theorems bound the limit load of non-associated flow by two associated ones:
// from above with the same yield surface (friction phi), from below with the largest surface
// inside it whose normals are the flow directions. For a joint, flows (tan psi, +-1) and (1, 0)
// in (sigma_n, tau), that surface is |tau| + sigma_n tan(psi) <= c with the same tension
// cut-off: friction psi, the same cohesion (it lies inside the original for sigma_n <= 0). At
// psi = 0 the lower bound is the cohesion-only pull-out, 2 c = 40 kN by plasticity theory
// (verified in tests/verification/pull_out_test.cpp).
TEST(NonAssociatedCollapse, PullOutCollapsesBetweenRadenkovicsBoundsForEveryDilation) {
  const double phi = 30.0;
  const Collapse upper = pull_out_collapse(phi, phi);
  for (const double psi : {0.0, 10.0, 20.0, 30.0}) {
    const Collapse c = pull_out_collapse(phi, psi);
    const Collapse lower = pull_out_collapse(psi, psi);
    EXPECT_EQ(c.stage, 1);
    EXPECT_FALSE(c.mechanism.empty()) << "psi " << psi;
    EXPECT_FALSE(c.unstable_at_first_load);
    EXPECT_LE(c.failed - c.carried, 2.0 * PlasticOptions{}.bracket_tolerance * c.failed);
    EXPECT_GE(c.failed, lower.carried) << "psi " << psi;
    EXPECT_LE(c.carried, upper.failed) << "psi " << psi;
    if (psi == 0.0) {
      EXPECT_NEAR(lower.failed * 120e3, 40e3, 40e3 * 1e-3);
      EXPECT_GT(c.carried * 120e3, 40e3);  // friction adds strength
    }
  }
}
// Displacement control passes the limit point of the equilibrium path: with dilation 0 the
// pulled half-brick slides at a constant load, the plateau, and that load is the bracket that
// load control proves by the complete method's exhausted searches (no solution beyond it).
TEST(NonAssociatedCollapse, DisplacementControlPlateausWhereLoadControlProvesTheCollapse) {
  const Collapse proven = pull_out_collapse(30.0, 0.0);
  CaseSpec c = pull_out_case(30.0, 0.0);
  StageSpec& pull = c.stages[1];
  pull.increments = 40;
  pull.control = DisplacementControlSpec{"A", Vec2::UnitX(), 4e-6, {0, "control"}};
  const PlasticResult r = run_plastic_analysis(build_model(c));
  ASSERT_FALSE(r.collapse.has_value());
  ASSERT_FALSE(r.stopped.has_value());
  // The last quarter of the stage is the plateau: every factor within the proven bracket.
  for (std::size_t k = r.history.size() - 10; k < r.history.size(); ++k) {
    EXPECT_GE(r.history[k].stage_factor, proven.carried * (1.0 - 1e-4)) << k;
    EXPECT_LE(r.history[k].stage_factor, proven.failed * (1.0 + 1e-4)) << k;
  }
}

// Where no solver decides a load-controlled increment (here: every LCP on the tangent, and no
// dense route or complete method behind it), displacement control of the block that moved most
// follows the path to its limit point. Its plateau is the collapse load that the complete
// method's exhausted searches prove with the default routes.
TEST(NonAssociatedCollapse, AnUndecidedIncrementIsFollowedToTheLimitPoint) {
  const Collapse proven = pull_out_collapse(30.0, 0.0);
  PlasticTuning tangent_only;
  tangent_only.solver.reduced_tangent_rows = 0;
  tangent_only.solver.dense_fallback_rows = 0;
  const PlasticResult r =
      run_plastic_analysis(build_model(pull_out_case(30.0, 0.0)), {}, {}, tangent_only);
  ASSERT_FALSE(r.stopped.has_value()) << r.stopped->reason;
  ASSERT_TRUE(r.collapse.has_value());
  const Collapse& c = *r.collapse;
  EXPECT_TRUE(c.limit_point);
  EXPECT_EQ(c.carried, c.failed);
  EXPECT_GE(c.carried, proven.carried * (1.0 - 1e-4));
  EXPECT_LE(c.carried, proven.failed * (1.0 + 1e-4));
  EXPECT_FALSE(c.mechanism.empty());
  // None of the pull's increments carried more than the limit load, and on its plateau the
  // pulled half-brick (monitor A) slides at least as far as the pull moves it elastically.
  double first = 0.0;
  double last = 0.0;
  for (const IncrementRecord& k : r.history) {
    if (k.stage != c.stage)
      continue;
    EXPECT_LE(k.stage_factor, c.carried);
    if (k.stage_factor >= c.carried * (1.0 - 1e-4)) {
      first = first == 0.0 ? k.monitors[0].x() : first;
      last = k.monitors[0].x();
    }
  }
  EXPECT_GT(c.elastic, 0.0);
  EXPECT_GE(c.plateau, c.elastic * (1.0 - 1e-9));
  EXPECT_GE(last - first, 0.5 * c.elastic) << "plateau from " << first << " to " << last;
}

// Without that search (and no solver to decide the increment), load control stops undecided.
// The same stages with associated flow then collapse, and by the static theorem no flow rule
// carries more than that load (Radenkovic's first theorem): the stop becomes a collapse
// bracketed between the load carried and a load that associated flow proves to fail, which
// contains the collapse load that the default routes prove.
TEST(NonAssociatedCollapse, AnUndecidedIncrementIsBracketedByAssociatedFlowsCollapse) {
  const Collapse proven = pull_out_collapse(30.0, 0.0);
  const Collapse associated = pull_out_collapse(30.0, 30.0);
  PlasticTuning tangent_only;
  tangent_only.solver.reduced_tangent_rows = 0;
  tangent_only.solver.dense_fallback_rows = 0;
  tangent_only.limit_point_increments = 0;
  const PlasticResult r =
      run_plastic_analysis(build_model(pull_out_case(30.0, 0.0)), {}, {}, tangent_only);
  ASSERT_FALSE(r.stopped.has_value()) << r.stopped->reason;
  ASSERT_TRUE(r.collapse.has_value());
  const Collapse& c = *r.collapse;
  EXPECT_TRUE(c.associated_bound);
  EXPECT_TRUE(c.undecided_inside);
  EXPECT_FALSE(c.limit_point);
  EXPECT_EQ(c.stage, 1);
  EXPECT_GT(c.carried, 0.0);  // the carried increments are kept
  EXPECT_EQ(c.carried, r.state.stage_factor);
  EXPECT_LE(c.carried, proven.failed * (1.0 + 1e-4));
  EXPECT_GE(c.failed, proven.carried * (1.0 - 1e-4));
  // A load proven to fail under associated flow (with these routes its bracket may be wider
  // than with the default ones), so no lower than associated flow's collapse load.
  EXPECT_GE(c.failed, associated.carried * (1.0 - 1e-4));
  EXPECT_FALSE(c.mechanism.empty());
}

// With a strength that softens the static theorem bounds nothing (the strength carried falls
// with the flow): the analysis stops, keeps what it carried, and says what to try.
TEST(NonAssociatedCollapse, AnUndecidedIncrementOfSofteningJointsStopsAndSaysWhatToTry) {
  PlasticTuning tangent_only;
  tangent_only.solver.reduced_tangent_rows = 0;
  tangent_only.solver.dense_fallback_rows = 0;
  tangent_only.limit_point_increments = 0;
  CaseSpec spec = pull_out_case(30.0, 0.0);
  for (JointMaterial& m : spec.joint_materials)
    if (m.strength)
      m.strength->cohesion = Softening{20e3, 10e3, 1.0};  // [Pa], over 1 m of slip
  const PlasticResult r = run_plastic_analysis(build_model(spec), {}, {}, tangent_only);
  ASSERT_TRUE(r.stopped.has_value());
  EXPECT_FALSE(r.collapse.has_value());
  EXPECT_NE(r.stopped->reason.find("prescribe a monitor's displacement"), std::string::npos)
      << r.stopped->reason;
  EXPECT_GT(r.stopped->factor, 0.0);
}

}  // namespace
}  // namespace bimrock
