// Random small blocky structures with random joint strength (friction 15-60 deg, dilation from
// 0 to the friction, cohesion zero or up to 20 kPa, no tension): gravity, then a lateral load
// that may or may not exceed their strength. Two families: columns of rectangular blocks, and
// walls cut into irregular blocks by inclined joints (T-junctions among them), which may not
// even carry their weight. Every analysis must end carried or with a proven collapse, never
// stopped. The state of every carried increment is checked against two laws independent of how
// its LCP was solved: the global balance of forces (the support reactions, integrated from the
// support springs' stresses, balance the applied loads) and every yield function at or below
// zero. Each outcome is checked against a second method, the rigid-block limit analysis of
// support/rigid_block_limit.hpp (a linear program, stage by stage): with associated flow the
// collapse load is its limit load, and with any other flow rule no load above it is carried
// (the static theorem).
#include <cmath>
#include <cstdio>
#include <random>
#include <string>
#include <utility>

#include <gtest/gtest.h>

#include <bimrock/analysis/factor_of_safety.hpp>
#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/analysis/strength_reduction.hpp>
#include <bimrock/assembly/yield_values.hpp>

#include "support/cases.hpp"
#include "support/degrees.hpp"
#include "support/irregular_blocks.hpp"
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

// The joint material of a random case, and its description.
JointMaterial random_joint(std::mt19937& rng, std::string& description) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  JointMaterial joint = testing::springs("joint", 1e10, 4e9);
  JointStrength s;
  const double phi = 15.0 + 45.0 * u(rng);
  const double psi = u(rng) < 0.4 ? 0.0 : phi * u(rng);
  const double cohesion = u(rng) < 0.5 ? 0.0 : 20e3 * u(rng);
  s.friction = Softening::constant(std::tan(phi * kDeg));
  s.dilation = std::tan(psi * kDeg);
  s.cohesion = Softening::constant(cohesion);
  joint.strength = s;
  description = "phi " + std::to_string(phi) + ", psi " + std::to_string(psi) + ", c " +
                std::to_string(cohesion);
  return joint;
}

// The blocks on a fixed base from 0 to `width` (its springs of the joint material), loaded by
// gravity (2 increments), then by a horizontal force `push` times the total weight at `at`
// (8 increments).
RandomCase loaded_case(const JointMaterial& joint, const std::string& joint_description,
                       const std::vector<Polygon>& blocks, double width, const Vec2& at,
                       double push) {
  RandomCase r;
  CaseSpec& c = r.spec;
  c.file = "random";
  c.block_materials = {testing::rock(20e9, 0.25, kUnitWeight)};
  c.joint_materials = {joint};
  c.default_joint = "joint";
  c.blocks = testing::blocks_of(blocks);
  double weight = 0.0;
  for (const Polygon& b : blocks)
    weight += kUnitWeight * signed_area(b);
  SupportSpec base = testing::fixed({0, 0}, {width, 0});
  base.joint_material = "joint";
  c.supports.push_back(base);
  StageSpec gravity{"gravity", {}, 2, std::nullopt, {0, "gravity"}};
  gravity.loads.gravity = Vec2(0, -1);
  StageSpec lateral{"push", {}, 8, std::nullopt, {0, "push"}};
  lateral.loads.points.push_back({at, Vec2(push * weight, 0.0), {0, "P"}});
  c.stages = {gravity, lateral};
  r.description = std::to_string(blocks.size()) + " blocks, " + joint_description +
                  ", force/weight " + std::to_string(push);
  return r;
}

// One or two columns of 1-3 rectangular blocks, pushed at the top block's top corner with
// 0.1-1.2 times their weight.
RandomCase random_columns(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string described;
  const JointMaterial joint = random_joint(rng, described);
  std::vector<Polygon> blocks;
  const int columns = u(rng) < 0.5 ? 1 : 2;
  double x = 0.0;
  Vec2 top_corner = Vec2::Zero();
  for (int col = 0; col < columns; ++col) {
    const double width = 0.5 + u(rng);
    const int rows = 1 + static_cast<int>(3.0 * u(rng));
    double y = 0.0;
    for (int row = 0; row < rows; ++row) {
      const double height = 0.3 + 0.9 * u(rng);
      blocks.push_back(Polygon{{{x, y}, {x + width, y}, {x + width, y + height}, {x, y + height}}});
      y += height;
    }
    if (col == 0)
      top_corner = Vec2(x, y);
    x += width;
  }
  const double push = 0.1 + 1.1 * u(rng);
  return loaded_case(joint, described, blocks, x, top_corner + Vec2(1e-3, -1e-3), push);
}

// A wall of 1-2 m by 0.8-2 m cut into irregular blocks by 2-5 joints, pushed near its top left
// corner with 0.05-0.6 times its weight.
RandomCase random_wall(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::string described;
  const JointMaterial joint = random_joint(rng, described);
  const double width = 1.0 + u(rng);
  const double height = 0.8 + 1.2 * u(rng);
  const int cuts = 2 + static_cast<int>(4.0 * u(rng));
  const auto seed = static_cast<unsigned>(1000.0 * u(rng));
  const double push = 0.05 + 0.55 * u(rng);
  return loaded_case(joint, described, testing::irregular_blocks(width, height, cuts, seed), width,
                     Vec2(1e-3, height - 1e-3), push);
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

// The rigid-block limit factors of the two stages: of the weight, and of the push on the whole
// weight (zero where the weight is not carried).
struct Limits {
  double gravity = 0.0;
  double push = 0.0;
};

Limits limits_of(const Model& model) {
  Limits l;
  l.gravity = testing::rigid_block_limit_factor(model, Loads{}, model.stages[0].loads).value();
  if (l.gravity >= 1.0)
    l.push = testing::rigid_block_limit_factor(model, model.stages[0].loads, model.stages[1].loads)
                 .value();
  return l;
}

// What the limit analysis allows: by the static theorem no flow rule carries more than the limit
// load of its stage, and associated flow collapses there, within the bracket tolerance.
void expect_within_limit_analysis(const PlasticResult& r, const Limits& limit, bool associated,
                                  const std::string& what) {
  constexpr double kRoundOff = 1e-6;
  constexpr double kBracket = 1e-4;  // PlasticOptions::bracket_tolerance, relative
  if (r.collapse) {
    const Collapse& c = *r.collapse;
    const double at = c.stage == 0 ? limit.gravity : limit.push;
    if (c.stage == 1) {
      EXPECT_GE(limit.gravity, 1.0 - kRoundOff) << what << ": carried more than its weight's limit";
    }
    EXPECT_LE(c.carried, at * (1.0 + kRoundOff)) << what << ": carried more than the limit load";
    if (associated) {
      EXPECT_GE(c.failed, at * (1.0 - kRoundOff)) << what << ": failed below the limit load";
      if (!c.unstable_at_first_load) {
        EXPECT_LE(c.failed - c.carried, kBracket * c.failed) << what;
      }
    }
  } else if (!r.stopped) {
    EXPECT_GE(limit.gravity, 1.0 - kRoundOff) << what << ": carried more than its weight's limit";
    EXPECT_GE(limit.push, 1.0 - kRoundOff) << what << ": carried more than the limit load";
  }
}

// Runs `trials` random cases of one family, each with its own flow rule and with associated
// flow, and checks each as the file's header says; returns how many of them (with their own
// flow rule) were carried and how many collapsed.
std::pair<int, int> check_family(RandomCase (*random)(std::mt19937&), unsigned seed, int trials,
                                 const std::string& family) {
  std::mt19937 rng(seed);
  int collapsed = 0;
  int carried = 0;
  for (int trial = 0; trial < trials; ++trial) {
    const RandomCase rc = random(rng);
    const Model model = build_model(rc.spec);
    const Limits limit = limits_of(model);
    const std::string what = family + " " + std::to_string(trial) + " (" + rc.description +
                             "), limit analysis " + std::to_string(limit.gravity) + ", " +
                             std::to_string(limit.push);
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
    EXPECT_FALSE(r.stopped.has_value()) << what << ": " << r.stopped->reason;
    EXPECT_LE(worst_balance, 1e-8) << what;
    // The analysis holds each yield function to 1e-9 of the larger stress of a state and of
    // its elastic prediction, which near a collapse passes the state's own many times over.
    EXPECT_LE(worst_yield, 1e-7) << what;
    if (r.collapse) {
      ++collapsed;
      // A limit point of the equilibrium path is its peak: carried = failed.
      if (r.collapse->limit_point) {
        EXPECT_EQ(r.collapse->carried, r.collapse->failed) << what;
      } else {
        EXPECT_LT(r.collapse->carried, r.collapse->failed) << what;
      }
    } else if (!r.stopped) {
      ++carried;
    }
    expect_within_limit_analysis(r, limit, false, what);
    const PlasticResult a =
        run_plastic_analysis(with_associated_flow(build_model(rc.spec)), PlasticOptions{});
    EXPECT_FALSE(a.stopped.has_value()) << what << ", associated: " << a.stopped->reason;
    expect_within_limit_analysis(a, limit, true, what + ", associated");
  }
  std::printf("%s: %d carried, %d collapsed\n", family.c_str(), carried, collapsed);
  return {carried, collapsed};
}

TEST(RandomStructures, EveryAnalysisOfColumnsEndsInBalanceWithinTheLimitAnalysis) {
  const auto [carried, collapsed] = check_family(random_columns, 2024, 100, "columns");
  // The family holds both outcomes.
  EXPECT_GT(collapsed, 10);
  EXPECT_GT(carried, 10);
}

TEST(RandomStructures, EveryAnalysisOfJointedWallsEndsInBalanceWithinTheLimitAnalysis) {
  // Some walls on cohesionless joints without dilation take 20 s each near their collapse (7-11
  // blocks, the complete method's searches of 57-81 rows); these 80 take about two seconds.
  // The reliability sweep (bench/random_sweep.py) measures the time such cases take. Among
  // these, wall 33 of seed 23 (10 blocks, friction 33.1 deg, dilation 0) has the first
  // increment of its weight solved only through the perturbed flows, where at one point both
  // slips stand for the opening (IncrementSolver::from_perturbed).
  for (const unsigned seed : {11U, 23U}) {
    const auto [carried, collapsed] = check_family(random_wall, seed, 40, "wall");
    EXPECT_GT(collapsed, 10) << "seed " << seed;
    EXPECT_GT(carried, 10) << "seed " << seed;
  }
}

TEST(RandomStructures, AssociatedFlowBracketsTheLimitOfAWallWhoseRoundsLeaveItsMechanismOut) {
  // Wall 23 of seed 17 (9 blocks on cohesionless joints of friction 27.5 deg) with associated
  // flow: past its limit load the LCPs of its first rounds, which leave the points outside
  // elastic, have solutions of flows so large that no pivoting method resolves them. The points
  // those flows violate join the next round, whose LCP has no solution.
  std::mt19937 rng(17);
  RandomCase rc;
  for (int trial = 0; trial <= 23; ++trial)
    rc = random_wall(rng);
  const Model model = with_associated_flow(build_model(rc.spec));
  const Limits limit = limits_of(model);
  const PlasticResult r = run_plastic_analysis(model, PlasticOptions{});
  ASSERT_TRUE(r.collapse.has_value()) << rc.description;
  EXPECT_EQ(r.collapse->stage, 1);
  EXPECT_FALSE(r.collapse->undecided_inside);
  expect_within_limit_analysis(r, limit, true, rc.description);
}

TEST(RandomStructures, FactorsOfSafetyOfJointedWallsBracketTheLimitAnalysis) {
  // The walls under their weight alone, and their factor of safety by strength reduction
  // against the rigid-block one (bisection on the linear program): no flow rule carries
  // strengths reduced beyond it, and associated flow fails there, within the tolerance.
  std::mt19937 rng(14);
  int below_one = 0;
  for (int trial = 0; trial < 20; ++trial) {
    RandomCase rc = random_wall(rng);
    rc.spec.stages.resize(1);
    const FactorOfSafetyOptions fos;
    const double limit = testing::rigid_block_factor_of_safety(build_model(rc.spec), fos.largest);
    below_one += limit < 1.0 ? 1 : 0;
    for (const bool associated : {false, true}) {
      const std::string what = "wall " + std::to_string(trial) + " (" + rc.description + ")" +
                               (associated ? ", associated" : "") + ", limit analysis " +
                               std::to_string(limit);
      PlasticOptions options;
      options.factor_of_safety = fos;
      const PlasticResult r = run_plastic_analysis(
          associated ? with_associated_flow(build_model(rc.spec)) : build_model(rc.spec), options);
      ASSERT_TRUE(r.factor_of_safety.has_value()) << what;
      const FactorOfSafety& f = *r.factor_of_safety;
      EXPECT_FALSE(f.undecided) << what;
      EXPECT_LE(f.lower, limit * (1.0 + 1e-6)) << what << ": carried weaker strengths";
      if (!associated)
        continue;
      if (f.collapse) {
        EXPECT_GE(f.collapse->failed, limit * (1.0 - 1e-6)) << what;
        EXPECT_LE(f.collapse->failed - f.lower, fos.tolerance * f.collapse->failed) << what;
      } else {
        EXPECT_GE(limit, fos.largest * (1.0 - 1e-6)) << what;
      }
    }
  }
  // The family holds walls that stand and walls that do not.
  EXPECT_GT(below_one, 2);
  EXPECT_LT(below_one, 18);
}

}  // namespace
}  // namespace bimrock
