// The brute-force oracle. Expected solution sets are worked by hand over all complementary
// bases (each test lists them).
#include <algorithm>

#include <gtest/gtest.h>

#include <bimrock/solve/lcp_enumeration.hpp>

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

bool contains(const std::vector<VectorXd>& set, const VectorXd& z) {
  return std::any_of(set.begin(), set.end(),
                     [&](const VectorXd& s) { return (s - z).cwiseAbs().maxCoeff() < 1e-12; });
}

TEST(LcpEnumeration, FindsTheHandSolvedSolutions) {
  // [2 1; 1 2], q = (-5, -6): A = {}: w = q < 0; A = {1}: z1 = 5/2, w2 = 5/2 - 6 < 0;
  // A = {2}: z2 = 3, w1 = 3 - 5 < 0; A = {1, 2}: z = (4/3, 7/3) >= 0. One solution.
  const auto s =
      enumerate_lcp_solutions({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-5.0, -6.0}}});
  ASSERT_EQ(s.size(), 1u);
  EXPECT_TRUE(contains(s, VectorXd{{4.0 / 3.0, 7.0 / 3.0}}));
}

TEST(LcpEnumeration, FindsEverySolutionOfANonPMatrix) {
  // [1 2; 2 1] (det -3: not a P-matrix), q = (-1, -1): A = {1}: z = (1, 0), w2 = 1;
  // A = {2}: z = (0, 1), w1 = 1; A = {1, 2}: z = (1/3, 1/3). Three solutions.
  const auto s =
      enumerate_lcp_solutions({MatrixXd{{1.0, 2.0}, {2.0, 1.0}}, VectorXd{{-1.0, -1.0}}});
  ASSERT_EQ(s.size(), 3u);
  EXPECT_TRUE(contains(s, VectorXd{{1.0, 0.0}}));
  EXPECT_TRUE(contains(s, VectorXd{{0.0, 1.0}}));
  EXPECT_TRUE(contains(s, VectorXd{{1.0 / 3.0, 1.0 / 3.0}}));
  // The solver returns one with the fewest active rows.
  const LcpResult r =
      LcpEnumeration().solve({MatrixXd{{1.0, 2.0}, {2.0, 1.0}}, VectorXd{{-1.0, -1.0}}});
  EXPECT_EQ(r.status, LcpStatus::solved);
  EXPECT_EQ((r.z.array() > 0.0).count(), 1);
}

TEST(LcpEnumeration, ReportsNoSolutionForInfeasibleProblems) {
  // M = 0, q = -1: w = -1 always. [1 -1; -1 1], q = (-1, -1): w1 + w2 = -2 always.
  EXPECT_EQ(LcpEnumeration().solve({MatrixXd{{0.0}}, VectorXd{{-1.0}}}).status,
            LcpStatus::no_solution);
  const LcpResult r =
      LcpEnumeration().solve({MatrixXd{{1.0, -1.0}, {-1.0, 1.0}}, VectorXd{{-1.0, -1.0}}});
  EXPECT_EQ(r.status, LcpStatus::no_solution);
  EXPECT_EQ(r.steps, 4);  // every basis tried
}

TEST(LcpEnumeration, SkipsSingularBasesButFindsTheSolutionOfADuplicatedRow) {
  // [1 1; 1 1], q = (-1, -1): A = {1, 2} is singular; A = {1} gives z = (1, 0) and w2 = 0,
  // A = {2} gives z = (0, 1). (Every z >= 0 with z1 + z2 = 1 solves it.)
  const auto s =
      enumerate_lcp_solutions({MatrixXd{{1.0, 1.0}, {1.0, 1.0}}, VectorXd{{-1.0, -1.0}}});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_TRUE(contains(s, VectorXd{{1.0, 0.0}}));
  EXPECT_TRUE(contains(s, VectorXd{{0.0, 1.0}}));
}

TEST(LcpEnumeration, RefusesLargeProblems) {
  const LcpProblem p{MatrixXd::Identity(21, 21), -VectorXd::Ones(21)};
  EXPECT_THROW((void)LcpEnumeration().solve(p), std::invalid_argument);
}

}  // namespace
}  // namespace bimrock
