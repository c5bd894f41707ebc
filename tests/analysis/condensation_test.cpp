// Regression: the LCPs solved on K condensed statically onto the plastic zone give the same
// analysis as on K itself.
//
// Source of the expected numbers: a second method on the same model. The abutment model of
// `bimrock bench` (a jointed mass, Mohr-Coulomb joints with associated flow, a thrust on a strip
// loaded to collapse) is run once with K itself (ZoneTuning::condensed_zone_fraction = 0)
// and once condensed onto zones as small as the candidate points allow (fraction 1, least zone
// 1 block): the carried stage factors, the monitor's displacements and the collapse bracket must
// agree. The condensed run must have condensed onto a part of the model and more than once (a
// zone outgrown and replaced), or the test proves nothing; with reserve zones in K's order, it
// must also have replaced a zone by a reserve; condensed in two steps (K onto a region, the
// region's S onto the zone), it must have condensed onto a region and onto a zone inside a
// region it had already (without factorizing K). The same under displacement control, whose
// monitor term must be read in the zone's unknowns.
#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/same_analysis.hpp"

namespace bimrock {
namespace {

PlasticTuning zones(const ZoneTuning& zones) {
  PlasticTuning t;
  t.solver.zones = zones;
  return t;
}

constexpr ZoneTuning kWhole{.condensed_zone_fraction = 0.0};
constexpr ZoneTuning kCondensed{.condensed_zone_fraction = 1.0,
                                .least_zone_blocks = 1,
                                .condense_after_blocks = 0,
                                .zone_reserves = 0,
                                .region_growth = 0.0};
constexpr ZoneTuning kReserves{.condensed_zone_fraction = 1.0,
                               .least_zone_blocks = 1,
                               .condense_after_blocks = 0,
                               .zone_reserves = 2,
                               .region_growth = 0.0};
constexpr ZoneTuning kRegions{.condensed_zone_fraction = 1.0,
                              .least_zone_blocks = 1,
                              .condense_after_blocks = 0,
                              .zone_reserves = 2,
                              .region_growth = 3.0,
                              .region_fraction = 1.0};

void expect_condensed(const PlasticResult& r, int blocks, const ZoneTuning& opt) {
  EXPECT_GE(r.condensations, 2) << "no zone was outgrown";
  if (opt.zone_reserves > 0)
    EXPECT_GE(r.reserve_switches, 1) << "no reserve zone was used";
  else
    EXPECT_EQ(r.reserve_switches, 0);
  if (opt.region_growth > 0.0) {
    EXPECT_GE(r.regions, 1) << "K was never condensed onto a region";
    EXPECT_GT(r.condensations, r.regions) << "no zone was condensed inside a region it had";
  } else {
    EXPECT_EQ(r.regions, 0);
  }
  EXPECT_GT(r.zone_blocks, 0);
  EXPECT_LT(r.zone_blocks, blocks) << "the last zone is the whole model";
  std::printf(
      "%d condensations (%d onto regions), %d reserves used, the last zone %d of %d "
      "blocks\n",
      r.condensations, r.regions, r.reserve_switches, r.zone_blocks, blocks);
}

TEST(Condensation, GivesTheSameAnalysisAsTheWholeStiffness) {
  const PlasticResult whole = testing::run_abutment(zones(kWhole));
  EXPECT_EQ(whole.condensations, 1);
  EXPECT_EQ(whole.zone_blocks, static_cast<int>(whole.state.u.size() / 6));
  for (const ZoneTuning& opt : {kCondensed, kReserves, kRegions}) {
    const PlasticResult condensed = testing::run_abutment(zones(opt));
    expect_condensed(condensed, static_cast<int>(whole.state.u.size() / 6), opt);
    testing::expect_same_analysis(whole, condensed);
  }
}

// Until the candidates touch more than ZoneTuning::condense_after_blocks blocks, the LCPs
// are solved on K itself: the same analysis whether that is never (more blocks than the
// model has: K is never condensed) or for the first increments only (the default), after
// which K is condensed as before.
TEST(Condensation, KItselfUntilManyBlocksAreNeededGivesTheSameAnalysis) {
  const PlasticResult whole = testing::run_abutment(zones(kWhole));
  ZoneTuning never = kReserves;
  never.condense_after_blocks = 1'000'000;
  const PlasticResult uncondensed = testing::run_abutment(zones(never));
  EXPECT_EQ(uncondensed.condensations, 0);
  testing::expect_same_analysis(whole, uncondensed);
  ZoneTuning later = kReserves;
  later.condense_after_blocks = ZoneTuning{}.condense_after_blocks;
  const PlasticResult condensed = testing::run_abutment(zones(later));
  EXPECT_GE(condensed.condensations, 1);
  EXPECT_LT(condensed.condensations, testing::run_abutment(zones(kReserves)).condensations);
  testing::expect_same_analysis(whole, condensed);
}

TEST(Condensation, UnderDisplacementControlGivesTheSameAnalysis) {
  // The monitor is driven to 70% of the displacement it had at the last load the abutment
  // carried under load control, along the way it moved, in 12 steps.
  const PlasticResult loaded = testing::run_abutment(zones(kWhole));
  ASSERT_TRUE(loaded.collapse.has_value());
  const Vec2 reached = loaded.history.back().monitors[0];
  CaseSpec c = abutment_case(100, 25, 1.2 * abutment_collapse_shear());
  StageSpec& stage = c.stages.back();
  stage.increments = 12;
  stage.control =
      DisplacementControlSpec{c.monitors[0].name, reached.normalized(), 0.7 * reached.norm(), {}};
  const Model model = build_model(c);
  const PlasticResult whole = run_plastic_analysis(model, {}, {}, zones(kWhole));
  ASSERT_FALSE(whole.collapse || whole.stopped);
  const auto expect_same = [&](const PlasticResult& condensed) {
    ASSERT_EQ(whole.history.size(), condensed.history.size());
    for (std::size_t i = 0; i < whole.history.size(); ++i) {
      const IncrementRecord& a = whole.history[i];
      const IncrementRecord& b = condensed.history[i];
      EXPECT_NEAR(b.stage_factor, a.stage_factor, 1e-7 * std::abs(a.stage_factor)) << i;
      EXPECT_NEAR((b.monitors[0] - a.monitors[0]).norm(), 0.0, 1e-7 * a.monitors[0].norm()) << i;
    }
    EXPECT_LE((condensed.state.u - whole.state.u).cwiseAbs().maxCoeff(),
              1e-7 * whole.state.u.cwiseAbs().maxCoeff());
  };
  for (const ZoneTuning& opt : {kCondensed, kReserves, kRegions}) {
    const PlasticResult condensed = run_plastic_analysis(model, {}, {}, zones(opt));
    expect_condensed(condensed, model.n_blocks(), opt);
    expect_same(condensed);
  }
  // K itself while few blocks are needed (its first LCPs need 20), then condensed: the monitor's
  // term is read from K, then in the zone's unknowns.
  ZoneTuning later = kReserves;
  later.condense_after_blocks = 40;
  const PlasticResult condensed = run_plastic_analysis(model, {}, {}, zones(later));
  EXPECT_GE(condensed.condensations, 1);
  expect_same(condensed);
}

}  // namespace
}  // namespace bimrock
