// Following the equilibrium path to its limit point (analysis/limit_point.hpp) on stand-in
// structures whose path is a closed form lambda(d) of the controlled displacement d: a trial
// from d by a step s carries to lambda(d + s). The limit point must be the path's plateau or
// peak, no increment past the stage's end may be carried, and a path that cannot be followed
// must not be taken for a limit point.
#include <algorithm>
#include <cmath>
#include <functional>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/limit_point.hpp>

namespace bimrock {
namespace {

// A stand-in structure: its state is the controlled displacement and the stage factor.
struct Path {
  std::function<double(double)> lambda;
  double end = 1e9;  // trials that would pass this displacement fail
  double d = 0.0;
  double factor = 0.0;
  std::vector<double> carried{};  // the factor after each carried trial

  LimitPoint follow(double from, double step, double plateau) {
    d = from;
    factor = lambda(from);
    const TryStep controlled = [&](double s, Thoroughness) {
      Trial t;
      if (d + s > end)
        return t;  // failed
      t.status = Trial::Status::carried;
      t.next.stage_factor = lambda(d + s);
      t.du = Eigen::VectorXd::Constant(1, s);
      return t;
    };
    const CarryStep carry = [&](const Trial& t) {
      d += t.du(0);
      factor = t.next.stage_factor;
      carried.push_back(factor);
    };
    LimitPointOptions options;
    options.step = step;
    options.plateau = plateau;
    return follow_to_limit_point(factor, controlled, carry, options);
  }
};

// Elastic-perfectly plastic: lambda rises as 0.8 d up to d = 1, then stays at 0.8 (a
// mechanism). The limit point is 0.8, once the plateau is 0.1 long: from d = 1.02, the first
// sample on it, to 1.14.
TEST(LimitPoint, APlateauIsTheLimitLoad) {
  Path path{[](double d) { return 0.8 * std::min(d, 1.0); }};
  const LimitPoint p = path.follow(0.9, 0.04, 0.1);
  ASSERT_EQ(p.outcome, LimitPoint::Outcome::limit_point);
  EXPECT_DOUBLE_EQ(p.peak, 0.8);
  EXPECT_NEAR(p.plateau, 0.12, 1e-12);
  EXPECT_FALSE(p.fell);
  EXPECT_NEAR(path.d, 1.14, 1e-12);
  ASSERT_TRUE(p.last.has_value());
  EXPECT_EQ(path.carried.size(), 6u);
}

// A plateau shorter than asked for is no limit point: lambda stays at 0.8 from d = 1 to 1.1 and
// then rises again (a joint that opened closes), past the stage's end at d = 1.2.
TEST(LimitPoint, APlateauThatEndsBeforeItsLengthIsNoLimitPoint) {
  Path path{[](double d) { return d < 1.1 ? 0.8 * std::min(d, 1.0) : 0.8 + 2.0 * (d - 1.1); }};
  const LimitPoint p = path.follow(0.9, 0.04, 0.2);
  EXPECT_EQ(p.outcome, LimitPoint::Outcome::rises);
  EXPECT_LE(path.factor, 1.0);
}

// A path that cannot be followed past d = 1.17 (its increments fail however cut): after three
// increments on its plateau past the one that reached it (d = 1.02; then 1.06, 1.10, 1.14),
// its peak is the limit point, at the plateau's length; after two (end at 1.13), nothing is
// proven.
TEST(LimitPoint, APathThatEndsOnItsPlateauEndsAtALimitPoint) {
  Path path{[](double d) { return 0.8 * std::min(d, 1.0); }, 1.17};
  const LimitPoint p = path.follow(0.9, 0.04, 1.0);
  ASSERT_EQ(p.outcome, LimitPoint::Outcome::limit_point);
  EXPECT_DOUBLE_EQ(p.peak, 0.8);
  // The parts that still carried past 1.14 are on the plateau too.
  EXPECT_GE(p.plateau, 0.12 - 1e-12);
  EXPECT_LE(p.plateau, 0.15 + 1e-12);
  Path shorter{[](double d) { return 0.8 * std::min(d, 1.0); }, 1.13};
  EXPECT_EQ(shorter.follow(0.9, 0.04, 1.0).outcome, LimitPoint::Outcome::undecided);
}

// Softening: lambda = 0.9 - 0.5 (d - 1)^2 has its peak 0.9 at d = 1. From d = 0.5 by steps of
// 0.1 the path is sampled at d = 0.6, 0.7, ..., and the largest sample, 0.9 at d = 1.0, is the
// limit point; the path is followed only until it falls.
TEST(LimitPoint, ThePeakOfAFallingPathIsTheLimitLoad) {
  Path path{[](double d) { return 0.9 - 0.5 * (d - 1.0) * (d - 1.0); }};
  const LimitPoint p = path.follow(0.5, 0.1, 1.0);
  ASSERT_EQ(p.outcome, LimitPoint::Outcome::limit_point);
  EXPECT_NEAR(p.peak, 0.9, 1e-12);
  EXPECT_LT(path.factor, p.peak);  // it went past the peak, to show it was one
  EXPECT_TRUE(p.fell);
  EXPECT_LE(path.d, 1.2 + 1e-12);
}

// A path that rises past the stage's end (1) has no limit point below it: nothing past the
// stage's end is carried, and load control goes on.
TEST(LimitPoint, APathRisingPastTheStageEndIsHandedBack) {
  Path path{[](double d) { return 0.3 * d; }};
  const LimitPoint p = path.follow(2.0, 0.5, 1.0);
  EXPECT_EQ(p.outcome, LimitPoint::Outcome::rises);
  ASSERT_FALSE(path.carried.empty());
  EXPECT_LE(*std::max_element(path.carried.begin(), path.carried.end()), 1.0);
  EXPECT_LE(path.factor, 1.0);
}

// Increments that no solve decides leave the search undecided, with nothing carried.
TEST(LimitPoint, UndecidedIncrementsAreNoLimitPoint) {
  int tried = 0;
  const TryStep never = [&](double, Thoroughness) {
    ++tried;
    return Trial{};  // failed
  };
  const CarryStep carry = [](const Trial&) { FAIL() << "nothing can be carried"; };
  LimitPointOptions options;
  options.step = 0.1;
  const LimitPoint p = follow_to_limit_point(0.7, never, carry, options);
  EXPECT_EQ(p.outcome, LimitPoint::Outcome::undecided);
  EXPECT_EQ(p.peak, 0.7);
  EXPECT_GT(tried, 0);
}

// The block whose centroid (u0, v0) moves most, whatever its rotation and strains.
TEST(LimitPoint, TheControlledBlockIsTheOneThatMovesMost) {
  Model model;
  model.blocks.resize(3);
  Eigen::VectorXd du = Eigen::VectorXd::Zero(18);
  du.segment<6>(0) << 0.1, 0.0, 5.0, 1.0, 1.0, 1.0;  // turns and strains, barely moves
  du.segment<6>(6) << 0.3, -0.4, 0.0, 0.0, 0.0, 0.0;
  du.segment<6>(12) << 0.0, 0.2, 0.0, 0.0, 0.0, 0.0;
  const ControlPoint c = most_moved_block(model, du);
  EXPECT_EQ(c.block, 1);
  EXPECT_NEAR(c.direction.x(), 0.6, 1e-15);
  EXPECT_NEAR(c.direction.y(), -0.8, 1e-15);
  EXPECT_EQ(most_moved_block(model, Eigen::VectorXd::Zero(18)).block, -1);
}

}  // namespace
}  // namespace bimrock
