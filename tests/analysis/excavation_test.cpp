// Excavation stages: the forces the excavated blocks exerted on the rest are released onto it.
// Elastic checks against a second analysis (superposition: the blocks left, loaded by their own
// weight from the start, end where excavating the others from a loaded mass ends), and the
// independence of the elastic result from the path (one or two stages, any release split, any
// number of increments); with yielding joints the path matters.
// Units: SI.
#include <algorithm>
#include <cmath>
#include <functional>

#include <gtest/gtest.h>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr int kColumns = 6;
constexpr int kRows = 4;

BlockSelector box(Vec2 lo, Vec2 hi) {
  BlockSelector s;
  s.kind = BlockSelector::Kind::box;
  s.box = BBox{lo, hi};
  s.source = {0, "stages[].excavate"};
  return s;
}

// A wall of unit squares [0, 6] x [0, 4] of rock on a fixed base, its joints elastic springs (or
// frictional ones), without the squares whose centres `skip` rejects; one stage of gravity.
CaseSpec wall(bool frictional, const std::function<bool(Vec2)>& skip = {}) {
  CaseSpec c;
  c.file = "wall";
  c.block_materials = {testing::rock(10e9, 0.2, 25e3)};
  JointMaterial joint = testing::springs("joint", 2e10, 1e10);
  if (frictional) {
    JointStrength s;
    s.friction = Softening::constant(std::tan(25.0 * M_PI / 180.0));
    joint.strength = s;
  }
  c.joint_materials = {joint};
  c.default_joint = "joint";
  std::vector<Polygon> squares;
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i)
      if (!skip || !skip(Vec2(i + 0.5, j + 0.5)))
        squares.push_back(Polygon{
            {{i + 0.0, j + 0.0}, {i + 1.0, j + 0.0}, {i + 1.0, j + 1.0}, {i + 0.0, j + 1.0}}});
  c.blocks = testing::blocks_of(squares);
  c.supports = {testing::fixed({0, 0}, {kColumns, 0})};
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0.0, -1.0);
  c.stages = {gravity};
  return c;
}

// The two squares at the top of the middle columns, and the one below them.
const Vec2 kLo(1.9, 1.9), kHi(4.1, 4.1);
bool in_opening(Vec2 centre) {
  return centre.x() > kLo.x() && centre.x() < kHi.x() && centre.y() > kLo.y() &&
         centre.y() < kHi.y();
}

StageSpec excavation(BBox where, int increments, double release = 1.0) {
  StageSpec st{"excavate", {}, increments, std::nullopt, {0, "stages[]"}};
  st.excavate = box(where.lo, where.hi);
  st.release = release;
  return st;
}

// The displacement of each block of `model` left at the end, in the order of the blocks of
// `left`, matched by centroid.
Eigen::VectorXd displacements_of(const Model& model, const Eigen::VectorXd& u, const Model& left) {
  Eigen::VectorXd out(left.n_dofs());
  for (int b = 0; b < left.n_blocks(); ++b) {
    int match = -1;
    for (int k = 0; k < model.n_blocks(); ++k)
      if ((model.blocks[k].centroid - left.blocks[b].centroid).norm() < 1e-9)
        match = k;
    EXPECT_GE(match, 0);
    out.segment<6>(6 * b) = u.segment<6>(6 * std::max(match, 0));
  }
  return out;
}

// The largest difference of the blocks that stand at the end (not in the opening: those keep
// the displacement they had when excavated), relative to the largest of b's.
double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  double difference = 0.0;
  for (int j = 0; j < kRows; ++j)
    for (int i = 0; i < kColumns; ++i) {
      if (in_opening(Vec2(i + 0.5, j + 0.5)))
        continue;
      const int block = j * kColumns + i;
      difference = std::max(difference, (a - b).segment<6>(6 * block).cwiseAbs().maxCoeff());
    }
  return difference / b.cwiseAbs().maxCoeff();
}

TEST(Excavation, AnElasticExcavationEndsWhereTheBlocksLeftStandUnderTheirWeight) {
  CaseSpec c = wall(false);
  c.stages.push_back(excavation(BBox{kLo, kHi}, 3));
  const Model model = build_model(c);
  ASSERT_EQ(model.stages[1].excavated.size(), 4u);
  const PlasticResult r = run_plastic_analysis(model);
  ASSERT_FALSE(r.collapse || r.stopped);
  EXPECT_EQ(r.stiffness_factorizations, 2);

  const Model left = build_model(wall(false, in_opening));
  ASSERT_EQ(left.n_blocks(), model.n_blocks() - 4);
  const PlasticResult alone = run_plastic_analysis(left);
  const Eigen::VectorXd excavated = displacements_of(model, r.state.u, left);
  EXPECT_LT((excavated - alone.state.u).cwiseAbs().maxCoeff(),
            1e-9 * alone.state.u.cwiseAbs().maxCoeff());
}

TEST(Excavation, TheElasticResultDoesNotDependOnThePath) {
  CaseSpec once = wall(false);
  once.stages.push_back(excavation(BBox{kLo, kHi}, 1));
  const Eigen::VectorXd u = run_plastic_analysis(build_model(once)).state.u;

  CaseSpec many = wall(false);
  many.stages.push_back(excavation(BBox{kLo, kHi}, 7));
  EXPECT_LT(relative_difference(run_plastic_analysis(build_model(many)).state.u, u), 1e-9);

  // The upper squares first, then the lower ones.
  CaseSpec two = wall(false);
  two.stages.push_back(excavation(BBox{{1.9, 2.9}, kHi}, 2));
  two.stages.push_back(excavation(BBox{kLo, {4.1, 3.1}}, 2));
  const PlasticResult r2 = run_plastic_analysis(build_model(two));
  EXPECT_EQ(r2.stiffness_factorizations, 3);
  EXPECT_LT(relative_difference(r2.state.u, u), 1e-9);

  // 40% released in the excavation's stage, the rest in the next (a stage of no load).
  CaseSpec split = wall(false);
  split.stages.push_back(excavation(BBox{kLo, kHi}, 2, 0.4));
  split.stages.push_back(StageSpec{"the rest", {}, 3, std::nullopt, {0, "stages[2]"}});
  const PlasticResult r3 = run_plastic_analysis(build_model(split));
  EXPECT_LT(relative_difference(r3.state.u, u), 1e-9);
  // After the first of them, 40% of the way from the loaded wall to the end.
  const Eigen::VectorXd loaded = run_plastic_analysis(build_model(wall(false))).state.u;
  CaseSpec part = wall(false);
  part.stages.push_back(excavation(BBox{kLo, kHi}, 2, 0.4));
  const Eigen::VectorXd at_40 = run_plastic_analysis(build_model(part)).state.u;
  EXPECT_LT(relative_difference(at_40, loaded + 0.4 * (u - loaded)), 1e-9);
}

// The wall under a horizontal in-situ stress of 2 MPa (0.5 MPa vertical, held by the same
// pressure on its top), between roller walls, its joints frictional (25 deg, associated).
CaseSpec stressed_wall() {
  CaseSpec c = wall(true);
  c.joint_materials[0].strength->dilation = c.joint_materials[0].strength->friction.value(0.0);
  c.supports = {testing::roller({0, 0}, {kColumns, 0}), testing::roller({0, 0}, {0, kRows}),
                testing::roller({kColumns, 0}, {kColumns, kRows})};
  c.stages[0].loads.gravity = Vec2::Zero();
  c.stages[0].loads.tractions = {testing::pressure_on({0, kRows}, {kColumns, kRows}, -0.5e6)};
  InitialStressSpec field;
  field.uniform = Eigen::Vector3d(-2e6, -0.5e6, 0.0);
  c.initial_stress = field;
  return c;
}

TEST(Excavation, WithYieldingJointsThePathMatters) {
  // The same opening excavated in one stage and in two: the horizontal stress flows round it
  // and the joints at its corners slip, differently on each path.
  CaseSpec once = stressed_wall();
  once.stages.push_back(excavation(BBox{kLo, kHi}, 4));
  const PlasticResult r1 = run_plastic_analysis(build_model(once));
  CaseSpec two = stressed_wall();
  two.stages.push_back(excavation(BBox{{1.9, 2.9}, kHi}, 4));
  two.stages.push_back(excavation(BBox{kLo, {4.1, 3.1}}, 4));
  const PlasticResult r2 = run_plastic_analysis(build_model(two));
  ASSERT_FALSE(r1.collapse || r1.stopped || r2.collapse || r2.stopped);
  double slip1 = 0.0, slip2 = 0.0;
  for (const PlasticState& p : r1.state.points)
    slip1 += p.slip;
  for (const PlasticState& p : r2.state.points)
    slip2 += p.slip;
  EXPECT_GT(slip1, 0.0);
  EXPECT_GT(slip2, 0.0);
  EXPECT_GT(relative_difference(r2.state.u, r1.state.u), 1e-3);
}

// The force the interfaces of `block` exert on it at the end of `r` (t = 1): the traction R
// along n and s on block i, its opposite on block j.
Vec2 interface_forces_on(const Model& model, const PlasticResult& r, int block) {
  YieldPointIndex index;
  static_cast<void>(make_yield_points(model, &index));
  Vec2 sum = Vec2::Zero();
  for (int k = 0; k < model.n_interfaces(); ++k) {
    const Interface& f = model.interfaces[k];
    if (f.block_i != block && f.block_j != block)
      continue;
    const InterfaceState st =
        interface_state(model, k, r.state.u, {&index, &r.state.points, &r.state.installed});
    Vec2 on_i = Vec2::Zero();
    for (const InterfacePointState& p : st)
      on_i += 0.5 * f.segment.length() * (p.stress(0) * f.normal + p.stress(1) * perp(f.normal));
    sum += f.block_i == block ? on_i : Vec2(-on_i);
  }
  return sum;
}

// Installing the top-left square after the wall has settled under its weight. Elastic, so
// superposition holds: the wall without the square under gravity, plus the whole wall under the
// square's weight alone (a point load at its centroid: gravity has no first moment there), the
// square itself moving from its installation. And the square's interfaces start unstressed: what
// they carry at the end is its weight.
TEST(Excavation, AnInstalledBlockIsPlacedUnstressedAndAddsItsWeight) {
  const Vec2 square(0.5, 3.5);
  const auto is_square = [&](Vec2 centre) { return (centre - square).norm() < 1e-9; };
  CaseSpec c = wall(false);
  StageSpec backfill{"backfill", {}, 3, std::nullopt, {0, "stages[1]"}};
  backfill.install = box({0.1, 3.1}, {0.9, 3.9});
  c.stages.push_back(backfill);
  const Model model = build_model(c);
  ASSERT_EQ(model.stages[1].installed.size(), 1u);
  const int installed = model.stages[1].installed.front();
  const PlasticResult r = run_plastic_analysis(model);
  ASSERT_FALSE(r.collapse || r.stopped);

  const Model without = build_model(wall(false, is_square));
  const Eigen::VectorXd settled = run_plastic_analysis(without).state.u;
  CaseSpec weight = wall(false);
  const double w = 25e3 * 1.0 * 1.0;  // unit weight x area x thickness [N]
  weight.stages.front().loads.gravity = Vec2::Zero();
  weight.stages.front().loads.points = {PointLoadSpec{square, Vec2(0.0, -w), {0, "load"}}};
  const Model whole = build_model(weight);
  const Eigen::VectorXd added = run_plastic_analysis(whole).state.u;

  Eigen::VectorXd expected = added;  // whole's blocks are model's, in the same order
  for (int b = 0; b < without.n_blocks(); ++b)
    for (int k = 0; k < model.n_blocks(); ++k)
      if ((model.blocks[k].centroid - without.blocks[b].centroid).norm() < 1e-9)
        expected.segment<6>(6 * k) += settled.segment<6>(6 * b);
  EXPECT_LT((r.state.u - expected).cwiseAbs().maxCoeff(), 1e-9 * expected.cwiseAbs().maxCoeff());

  // The square's equilibrium: its interfaces push it up by its weight, no more.
  const Vec2 carried = interface_forces_on(model, r, installed);
  EXPECT_NEAR(carried.x(), 0.0, 1e-9 * w);
  EXPECT_NEAR(carried.y(), w, 1e-9 * w);
}

// The same with frictional joints, whose yield points must start unstressed too (else they
// would yield under what the wall's settlement did before the square was there).
TEST(Excavation, AnInstalledBlocksYieldPointsStartUnstressed) {
  CaseSpec c = wall(true);
  StageSpec backfill{"backfill", {}, 3, std::nullopt, {0, "stages[1]"}};
  backfill.install = box({0.1, 3.1}, {0.9, 3.9});
  c.stages.push_back(backfill);
  const Model model = build_model(c);
  const PlasticResult r = run_plastic_analysis(model);
  ASSERT_FALSE(r.collapse || r.stopped);
  const Vec2 carried = interface_forces_on(model, r, model.stages[1].installed.front());
  const double w = 25e3;
  EXPECT_NEAR(carried.x(), 0.0, 1e-9 * w);
  EXPECT_NEAR(carried.y(), w, 1e-9 * w);
}

}  // namespace
}  // namespace bimrock
