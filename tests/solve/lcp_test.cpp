// The LCP data object and its residuals. Expected numbers are worked by hand.
#include <sstream>

#include <gtest/gtest.h>

#include <bimrock/solve/lcp.hpp>

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

}  // namespace
}  // namespace bimrock
