// least_norm_pivoting(): from a point near a solution to an exact one, on an LCP of the shape a
// cohesionless joint at dilation 0 gives (opposite slip flows, whose columns of M cancel), where
// the solution's active block is singular. Checked on the LCP's own conditions (measure()).
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/LU>

#include <bimrock/solve/least_norm_pivoting.hpp>

namespace bimrock {
namespace {

// Two joint points (rows: opening, slip +, slip -) on a body of stiffness K: M = C K^-1 Phi with
// the flows (normal; +-shear, no dilation) and the gradients (normal; +-shear + mu normal), the
// shape of eq. 28 with N = 0 (each flow relieves its own yield function: a positive diagonal).
LcpProblem two_joint_points(const Eigen::VectorXd& z, const Eigen::VectorXd& w) {
  const double mu = 0.7;
  Eigen::MatrixXd k(4, 4);
  k << 4, 1, 0, 0.5,  //
      1, 3, 0.2, 0,   //
      0, 0.2, 5, 1,   //
      0.5, 0, 1, 2;
  // Unknowns: normal and shear displacement of each point.
  Eigen::MatrixXd phi = Eigen::MatrixXd::Zero(4, 6);
  Eigen::MatrixXd c = Eigen::MatrixXd::Zero(6, 4);
  for (int p = 0; p < 2; ++p) {
    const int n = 2 * p;
    const int s = 2 * p + 1;
    phi(n, 3 * p) = 1.0;
    phi(s, 3 * p + 1) = 1.0;
    phi(s, 3 * p + 2) = -1.0;
    c(3 * p, n) = 1.0;
    c(3 * p + 1, s) = 1.0;
    c(3 * p + 1, n) = mu;
    c(3 * p + 2, s) = -1.0;
    c(3 * p + 2, n) = mu;
  }
  LcpProblem problem{c * k.inverse() * phi, Eigen::VectorXd::Zero(6)};
  problem.q = w - problem.m * z;
  return problem;
}

TEST(LeastNormPivoting, SolvesWhereTheActiveBlockIsSingular) {
  // The solution: point 0 open and slipping (all three rows active, both slip multipliers
  // positive: only their difference is determined), point 1 sliding along slip + alone.
  Eigen::VectorXd z_star(6);
  z_star << 0.5, 0.2, 0.2, 0.0, 0.3, 0.0;
  Eigen::VectorXd w_star(6);
  w_star << 0.0, 0.0, 0.0, 0.7, 0.0, 0.4;
  const LcpProblem problem = two_joint_points(z_star, w_star);
  ASSERT_LE(measure(problem, z_star).worst_relative(), 1e-12);
  // Its active block is singular: the slip columns of point 0 cancel.
  const std::vector<Eigen::Index> active{0, 1, 2, 4};
  EXPECT_EQ(Eigen::FullPivLU<Eigen::MatrixXd>(problem.m(active, active)).rank(), 3);

  // Near it, with row 3 wrongly active and the slip multipliers of point 0 unequal.
  Eigen::VectorXd near(6);
  near << 0.45, 0.3, 0.12, 0.05, 0.25, 0.0;
  const std::optional<LcpResult> r = least_norm_pivoting(problem, near, 1e-9, 10, 7);
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->status, LcpStatus::solved);
  EXPECT_EQ(r->steps, 7);
  EXPECT_LE(measure(problem, r->z).worst_relative(), 1e-9);
  EXPECT_GE(r->z.minCoeff(), 0.0);
  // The determined parts of the solution: the opening, the net slip of point 0, point 1's slip.
  EXPECT_NEAR(r->z(0), z_star(0), 1e-12);
  EXPECT_NEAR(r->z(1) - r->z(2), z_star(1) - z_star(2), 1e-12);
  EXPECT_NEAR(r->z(4), z_star(4), 1e-12);
  EXPECT_EQ(r->z(3), 0.0);
}

TEST(LeastNormPivoting, GivesUpFarFromAnySolution) {
  // q with every row violated and M = -I: w = -z + q < 0 for every z >= 0, no solution.
  const LcpProblem problem{-Eigen::MatrixXd::Identity(3, 3), Eigen::VectorXd::Constant(3, -1.0)};
  EXPECT_FALSE(least_norm_pivoting(problem, Eigen::VectorXd::Ones(3), 1e-9, 10, 0).has_value());
}

}  // namespace
}  // namespace bimrock
