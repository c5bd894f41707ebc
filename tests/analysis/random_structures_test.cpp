// Random small blocky structures with random joint strength (friction 15-60 deg, dilation from
// 0 to the friction, cohesion zero or up to 20 kPa, no tension): gravity, then a lateral load
// that may or may not exceed their strength. Every analysis must end carried or with a proven
// collapse, never stopped. The state of every carried increment is checked against two laws
// independent of how its LCP was solved: the global balance of forces (the support reactions,
// integrated from the support springs' stresses, balance the applied loads) and every yield
// function at or below zero. Each outcome is checked against a second method, the rigid-block
// limit analysis of support/rigid_block_limit.hpp (a linear program): with associated flow the
// collapse load is its limit load, and with any other flow rule no load above it is carried
// (the static theorem).
#include <cmath>
#include <cstdio>
#include <random>

#include <gtest/gtest.h>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/assembly/yield_values.hpp>

#include "support/cases.hpp"
#include "support/degrees.hpp"
#include "support/rigid_block_limit.hpp"
#include "support/support_reaction.hpp"

namespace bimrock {
namespace {

using testing::kDeg;
constexpr double kUnitWeight = 25e3;  // [N/m^3]

struct RandomCase {
  CaseSpec spec;
  std::string description;
};

// One or two columns of 1-3 rectangular blocks on a fixed base (its springs of the same joint
// material), loaded by gravity (2 increments), then a horizontal force at the top block's top
// corner of 0.1-1.2 times the total weight (8 increments).
RandomCase random_case(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RandomCase r;
  CaseSpec& c = r.spec;
  c.file = "random";
  c.block_materials = {testing::rock(20e9, 0.25, kUnitWeight)};
  JointMaterial joint = testing::springs("joint", 1e10, 4e9);
  JointStrength s;
  const double phi = 15.0 + 45.0 * u(rng);
  const double psi = u(rng) < 0.4 ? 0.0 : phi * u(rng);
  const double cohesion = u(rng) < 0.5 ? 0.0 : 20e3 * u(rng);
  s.friction = Softening::constant(std::tan(phi * kDeg));
  s.dilation = std::tan(psi * kDeg);
  s.cohesion = Softening::constant(cohesion);
  joint.strength = s;
  c.joint_materials = {joint};
  c.default_joint = "joint";
  std::vector<Polygon> blocks;
  const int columns = u(rng) < 0.5 ? 1 : 2;
  double x = 0.0;
  double weight = 0.0;
  Vec2 top_corner = Vec2::Zero();
  for (int col = 0; col < columns; ++col) {
    const double width = 0.5 + u(rng);
    const int rows = 1 + static_cast<int>(3.0 * u(rng));
    double y = 0.0;
    for (int row = 0; row < rows; ++row) {
      const double height = 0.3 + 0.9 * u(rng);
      blocks.push_back(Polygon{{{x, y}, {x + width, y}, {x + width, y + height}, {x, y + height}}});
      weight += kUnitWeight * width * height;
      y += height;
    }
    if (col == 0)
      top_corner = Vec2(x, y);
    x += width;
  }
  c.blocks = testing::blocks_of(blocks);
  SupportSpec base = testing::fixed({0, 0}, {x, 0});
  base.joint_material = "joint";
  c.supports.push_back(base);
  StageSpec gravity{"gravity", {}, 2, std::nullopt, {0, "gravity"}};
  gravity.loads.gravity = Vec2(0, -1);
  StageSpec push{"push", {}, 8, std::nullopt, {0, "push"}};
  const double force = (0.1 + 1.1 * u(rng)) * weight;
  push.loads.points.push_back({top_corner + Vec2(1e-3, -1e-3), Vec2(force, 0.0), {0, "P"}});
  c.stages = {gravity, push};
  r.description = std::to_string(blocks.size()) + " blocks, phi " + std::to_string(phi) + ", psi " +
                  std::to_string(psi) + ", c " + std::to_string(cohesion) + ", force/weight " +
                  std::to_string(force / weight);
  return r;
}

// The loads applied at the end of `stage` with its factor: the earlier stages whole.
Vec2 applied_force(const CaseSpec& c, const Model& model, int stage, double factor) {
  Vec2 total = Vec2::Zero();
  for (int st = 0; st <= stage; ++st) {
    const double f = st < stage ? 1.0 : factor;
    const StageSpec& s = c.stages[static_cast<std::size_t>(st)];
    for (const Block& b : model.blocks)
      total += f * kUnitWeight * b.area * model.settings.thickness * s.loads.gravity;
    for (const PointLoadSpec& p : s.loads.points)
      total += f * p.force;
  }
  return total;
}

// The same case with each dilation equal to its friction.
CaseSpec with_associated_flow(CaseSpec c) {
  for (JointMaterial& m : c.joint_materials)
    m.strength->dilation = m.strength->friction.peak;
  return c;
}

// The push's factors that the structures' rigid-block limit analysis (`limit`) allows: by the
// static theorem no flow rule carries more, and associated flow collapses there.
void expect_within_limit_analysis(const PlasticResult& r, double limit, bool associated,
                                  const std::string& what) {
  constexpr double kTolerance = 1e-4;  // PlasticOptions::bracket_tolerance, relative
  if (r.collapse) {
    EXPECT_EQ(r.collapse->stage, 1) << what << ": gravity alone never fails a column on a base";
    EXPECT_LE(r.collapse->carried, limit * (1.0 + 1e-6)) << what;
    if (associated) {
      EXPECT_GE(r.collapse->failed, limit * (1.0 - 1e-6)) << what;
      EXPECT_LE(r.collapse->failed - r.collapse->carried, kTolerance * r.collapse->failed) << what;
    }
  } else if (!r.stopped) {
    EXPECT_LE(1.0, limit * (1.0 + 1e-6)) << what << ": carried more than the limit load";
    if (associated) {
      EXPECT_GE(limit, 1.0) << what;
    }
  }
}

TEST(RandomStructures, EveryAnalysisCarriesOrProvesItsCollapseInBalance) {
  std::mt19937 rng(2024);
  int collapsed = 0;
  int carried = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const RandomCase rc = random_case(rng);
    const Model model = build_model(rc.spec);
    const std::optional<double> limit =
        testing::rigid_block_limit_factor(model, model.stages[0].loads, model.stages[1].loads);
    ASSERT_TRUE(limit.has_value()) << "trial " << trial << ": its weight alone is carried";
    YieldPointIndex index;
    const std::vector<YieldPoint> points = make_yield_points(model, &index);
    const YieldEvaluator yield(model, points);
    double worst_balance = 0.0;
    double worst_yield = 0.0;
    const PlasticResult r = run_plastic_analysis(
        model, PlasticOptions{}, [&](const IncrementRecord& rec, const AnalysisState& state) {
          const PlasticParts plastic{&index, &state.points};
          const Vec2 load = applied_force(rc.spec, model, rec.stage, rec.stage_factor);
          const Vec2 reaction = testing::support_reaction(model, state.u, plastic);
          worst_balance =
              std::max(worst_balance, (load + reaction).norm() / std::max(load.norm(), 1.0));
          YieldValues f;
          double scale = 0.0;
          yield.evaluate(state.points, state.u, f, &scale);
          worst_yield = std::max(worst_yield, f.f.maxCoeff() / std::max(scale, 1.0));
        });
    EXPECT_FALSE(r.stopped.has_value())
        << "trial " << trial << " (" << rc.description << "): " << r.stopped->reason;
    EXPECT_LE(worst_balance, 1e-8) << "trial " << trial << " (" << rc.description << ")";
    EXPECT_LE(worst_yield, 1e-8) << "trial " << trial << " (" << rc.description << ")";
    if (r.collapse) {
      ++collapsed;
      EXPECT_LT(r.collapse->carried, r.collapse->failed) << "trial " << trial;
    } else if (!r.stopped) {
      ++carried;
    }
    const std::string what = "trial " + std::to_string(trial) + " (" + rc.description +
                             "), limit analysis " + std::to_string(*limit);
    expect_within_limit_analysis(r, *limit, false, what);
    const PlasticResult a =
        run_plastic_analysis(build_model(with_associated_flow(rc.spec)), PlasticOptions{});
    EXPECT_FALSE(a.stopped.has_value()) << what << ", associated: " << a.stopped->reason;
    expect_within_limit_analysis(a, *limit, true, what + ", associated");
  }
  std::printf("%d carried, %d collapsed\n", carried, collapsed);
  // The family holds both outcomes.
  EXPECT_GT(collapsed, 10);
  EXPECT_GT(carried, 10);
}

}  // namespace
}  // namespace bimrock
