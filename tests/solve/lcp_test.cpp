// The LCP data object, its residuals and the reach of an infeasibility certificate. Expected
// numbers are worked by hand (and the certificate's reach is checked with Lemke as well).
#include <cmath>
#include <limits>
#include <sstream>

#include <gtest/gtest.h>

#include <bimrock/solve/lcp.hpp>
#include <bimrock/solve/lemke.hpp>

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

const LcpProblem kProblem{MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-1.0, 3.0}}};

TEST(LcpResiduals, OfTheExactSolutionAreZero) {
  // z = (1/2, 0): w = (0, 7/2).
  const LcpResiduals r = measure(kProblem, VectorXd{{0.5, 0.0}});
  EXPECT_EQ(r.min_z, 0.0);
  EXPECT_EQ(r.min_w, 0.0);
  EXPECT_EQ(r.max_complementarity, 0.0);
  EXPECT_EQ(r.worst_relative(), 0.0);
}

TEST(LcpResiduals, MeasureEachViolationAbsoluteAndRelative) {
  // z = (1, -0.1): w = (2 - 0.1 - 1, 1 - 0.2 + 3) = (0.9, 3.8).
  // Row scales s = |q| + |M| |z| = (1 + 2 + 0.1, 3 + 1 + 0.2) = (3.1, 4.2); |z|_inf = 1.
  const LcpResiduals r = measure(kProblem, VectorXd{{1.0, -0.1}});
  EXPECT_DOUBLE_EQ(r.min_z, -0.1);
  EXPECT_DOUBLE_EQ(r.min_w, 0.9);
  EXPECT_DOUBLE_EQ(r.max_complementarity, 0.9);  // |1 * 0.9| > |-0.1 * 3.8|
  EXPECT_DOUBLE_EQ(r.z_violation, 0.1);
  EXPECT_EQ(r.w_violation, 0.0);
  EXPECT_DOUBLE_EQ(r.complementarity, 0.9 / 3.1);  // pair 1: min(1/1, 0.9/3.1)
  EXPECT_DOUBLE_EQ(r.worst_relative(), 0.9 / 3.1);
}

TEST(LcpResiduals, RelativeMeasuresIgnoreRowScaling) {
  const VectorXd z{{1.0, -0.1}};
  const VectorXd d{{1e8, 1e-3}};
  const LcpProblem scaled{d.asDiagonal() * kProblem.m, d.cwiseProduct(kProblem.q)};
  EXPECT_NEAR(measure(scaled, z).worst_relative(), measure(kProblem, z).worst_relative(), 1e-15);
}

TEST(LcpResiduals, ViolatedRowOfZeroMatrix) {
  // M = 0, q = -1, z = 0: w = -1, row scale |q| = 1: fully violated.
  const LcpResiduals r = measure({MatrixXd{{0.0}}, VectorXd{{-1.0}}}, VectorXd{{0.0}});
  EXPECT_EQ(r.min_w, -1.0);
  EXPECT_EQ(r.w_violation, 1.0);
}

TEST(LcpResiduals, ANonFiniteIterateFailsEveryCheck) {
  // NaN compares false with everything: without care it would leave the maxima at 0 and pass.
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const VectorXd& z : {VectorXd{{nan, 0.0}}, VectorXd{{0.5, nan}},
                            VectorXd{{std::numeric_limits<double>::infinity(), 0.0}}}) {
    const LcpResiduals r = measure(kProblem, z);
    EXPECT_FALSE(r.worst_relative() <= 1.0);
    EXPECT_FALSE(r.z_violation <= 1.0);
    EXPECT_FALSE(r.w_violation <= 1.0);
  }
  // q itself not finite: w is not.
  const LcpProblem broken{kProblem.m, VectorXd{{nan, 3.0}}};
  EXPECT_FALSE(measure(broken, VectorXd{{0.0, 0.0}}).worst_relative() <= 1.0);
}

TEST(LcpProblem, RoundTripsThroughTextExactly) {
  LcpProblem p{MatrixXd{{0.1, 1.0 / 3.0}, {-2e-300, 1e300}}, VectorXd{{-0.7, 5e-17}}};
  std::stringstream s;
  write_lcp(s, p);
  const LcpProblem back = read_lcp(s);
  EXPECT_EQ(back.m, p.m);
  EXPECT_EQ(back.q, p.q);
}

TEST(LcpProblem, ReadingATruncatedStreamThrows) {
  std::stringstream s("bimrock-lcp 1\n2\n1 2 3\n");
  EXPECT_THROW((void)read_lcp(s), std::runtime_error);
}

TEST(LcpProblem, MismatchedSizesAreRejected) {
  EXPECT_THROW(check_lcp({MatrixXd(2, 3), VectorXd(2)}), std::invalid_argument);
  EXPECT_THROW(check_lcp({MatrixXd::Zero(2, 2), VectorXd(3)}), std::invalid_argument);
}

// M = [1 -1; -1 1] is singular with kernel r = (1, 1); q(s) = (1 - 3 s, 1 + s) for a load step
// s. q(s) . r = 2 - 2 s: r certifies no solution for s > 1, and for s <= 1 z = (3 s - 1, 0)
// (or z = 0 while s <= 1/3) solves it. So a ray found at s = 1.5 proves every step from
// 1 / 1.5 of it on.
TEST(CertifiedFrom, IsWhereTheLoadMakesTheCertificateHold) {
  const MatrixXd m{{1.0, -1.0}, {-1.0, 1.0}};
  const auto q = [](double s) { return VectorXd{{1.0 - 3.0 * s, 1.0 + s}}; };
  const VectorXd r{{1.0, 1.0}};
  const double step = 1.5;
  const double t = certified_from(q(step), q(step) - q(0.0), r);
  EXPECT_NEAR(t * step, 1.0, 1e-7);
  EXPECT_GT(t * step, 1.0);  // the tolerance of the certificate lies on the safe side
  EXPECT_EQ(Lemke().solve({m, q(0.999 * t * step)}).status, LcpStatus::solved);
  EXPECT_EQ(Lemke().solve({m, q(1.001 * t * step)}).status, LcpStatus::no_solution);
  // A load that does not drive the mechanism (q . r grows with it: at no step q . r = -4)
  // proves no less than the step itself.
  EXPECT_EQ(certified_from(VectorXd{{-3.0, 1.0}}, VectorXd{{1.0, 1.0}}, r), 1.0);
}

// q and s q with s > 0 are one LCP; a negative multiple, a q changed in one entry by 1e-9,
// or an M changed in its last bit are not.
TEST(LcpProblem, SameUpToScaleIsAPositiveMultipleOfQWithTheSameM) {
  const LcpProblem scaled{kProblem.m, 3.5 * kProblem.q};
  EXPECT_TRUE(same_up_to_scale(kProblem, scaled));
  EXPECT_TRUE(same_up_to_scale(scaled, kProblem));
  EXPECT_FALSE(same_up_to_scale(kProblem, {kProblem.m, -kProblem.q}));
  LcpProblem moved = scaled;
  moved.q(1) += 1e-9;
  EXPECT_FALSE(same_up_to_scale(kProblem, moved));
  LcpProblem other_m = scaled;
  other_m.m(0, 1) = std::nextafter(other_m.m(0, 1), 2.0);
  EXPECT_FALSE(same_up_to_scale(kProblem, other_m));
  EXPECT_FALSE(same_up_to_scale(kProblem, {MatrixXd::Identity(3, 3), VectorXd::Ones(3)}));
}

}  // namespace
}  // namespace bimrock
