// Projected Gauss-Seidel, the second method: checked against hand solutions and against
// Lemke (itself checked against the enumeration oracle) on larger positive definite problems,
// whose solution is unique, so the two independent methods must agree.
#include <gtest/gtest.h>

#include <bimrock/solve/lemke.hpp>
#include <bimrock/solve/projected_gauss_seidel.hpp>

#include "solve/random_lcp.hpp"

namespace bimrock {
namespace {

using Eigen::MatrixXd;
using Eigen::VectorXd;

TEST(ProjectedGaussSeidel, TwoByTwoByHand) {
  // [2 1; 1 2] z = (5, 6): z = (4/3, 7/3) (Cramer's rule), both rows active.
  ProjectedGaussSeidel pgs;
  const LcpResult r = pgs.solve({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{-5.0, -6.0}}});
  ASSERT_EQ(r.status, LcpStatus::solved);
  EXPECT_LE(r.residuals.worst_relative(), 1e-10);
  EXPECT_NEAR(r.z(0), 4.0 / 3.0, 1e-9);
  EXPECT_NEAR(r.z(1), 7.0 / 3.0, 1e-9);
}

TEST(ProjectedGaussSeidel, NonnegativeQNeedsNoSweep) {
  ProjectedGaussSeidel pgs;
  const LcpResult r = pgs.solve({MatrixXd{{2.0, 1.0}, {1.0, 2.0}}, VectorXd{{1.0, 0.0}}});
  EXPECT_EQ(r.status, LcpStatus::solved);
  EXPECT_EQ(r.steps, 0);
  EXPECT_EQ(r.z, VectorXd::Zero(2));
}

class PgsVsLemke : public ::testing::TestWithParam<int> {};

TEST_P(PgsVsLemke, AgreeOnPositiveDefiniteProblems) {
  const int n = GetParam();
  std::mt19937 rng(static_cast<unsigned>(n));
  const LcpProblem p{testing::random_spd(n, rng), testing::random_vector(n, rng)};
  const LcpResult reference = Lemke().solve(p);
  ASSERT_EQ(reference.status, LcpStatus::solved);
  for (double omega : {1.0, 1.3}) {
    PgsOptions options;
    options.relaxation = omega;
    const LcpResult r = ProjectedGaussSeidel(options).solve(p);
    SCOPED_TRACE("omega " + std::to_string(omega));
    ASSERT_EQ(r.status, LcpStatus::solved);
    EXPECT_LE(r.residuals.worst_relative(), 1e-10);
    // M has eigenvalues >= 1, so |z - z*| is bounded by the residual's size.
    EXPECT_LE((r.z - reference.z).cwiseAbs().maxCoeff(), 1e-8 * reference.z.cwiseAbs().maxCoeff());
  }
}

INSTANTIATE_TEST_SUITE_P(Sizes, PgsVsLemke, ::testing::Values(50, 100, 200));

TEST(ProjectedGaussSeidel, WarmStartFromTheSolutionStopsAtOnce) {
  std::mt19937 rng(3);
  const LcpProblem p{testing::random_spd(30, rng), testing::random_vector(30, rng)};
  const LcpResult reference = Lemke().solve(p);
  ASSERT_EQ(reference.status, LcpStatus::solved);
  ProjectedGaussSeidel pgs;
  const LcpResult cold = pgs.solve(p);
  const LcpResult warm = pgs.solve(p, &reference.z);
  EXPECT_EQ(warm.status, LcpStatus::solved);
  EXPECT_LE(warm.steps, 1);
  EXPECT_GT(cold.steps, 1);
}

TEST(ProjectedGaussSeidel, InfeasibleProblemRunsIntoTheIterationLimit) {
  // [1 -1; -1 1], q = (-1, -1) has no solution (w1 + w2 = -2): the iteration cannot prove it.
  PgsOptions options;
  options.max_iterations = 500;
  const LcpResult r = ProjectedGaussSeidel(options).solve(
      {MatrixXd{{1.0, -1.0}, {-1.0, 1.0}}, VectorXd{{-1.0, -1.0}}});
  EXPECT_EQ(r.status, LcpStatus::iteration_limit);
  EXPECT_EQ(r.steps, 500);
  EXPECT_GT(r.residuals.worst_relative(), options.tolerance);
}

TEST(ProjectedGaussSeidel, ZeroDiagonalIsRejected) {
  const LcpResult r =
      ProjectedGaussSeidel().solve({MatrixXd{{0.0, 1.0}, {1.0, 1.0}}, VectorXd{{-1.0, -1.0}}});
  EXPECT_EQ(r.status, LcpStatus::numerical_failure);
  EXPECT_EQ(r.steps, 0);
}

}  // namespace
}  // namespace bimrock
