// The measured accuracy of the solves with a factor of K against the bound of backward-stable
// Cholesky (forward error of order cond(K) x machine precision): matrices of known condition,
// Q diag(d) Q^T with a random orthogonal Q and eigenvalues d from 1 to 1/cond.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/solve/solve_accuracy.hpp>
#include <bimrock/solve/sparse_cholesky.hpp>

namespace bimrock {
namespace {

// The lower triangle of an n x n symmetric matrix of condition number `cond`.
CholmodMatrix conditioned(int n, double cond, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      a(i, j) = normal(rng);
  const Eigen::MatrixXd q = Eigen::HouseholderQR<Eigen::MatrixXd>(a).householderQ();
  Eigen::VectorXd d(n);
  for (int i = 0; i < n; ++i)
    d(i) = std::pow(cond, -static_cast<double>(i) / (n - 1));
  const Eigen::MatrixXd k = q * d.asDiagonal() * q.transpose();
  const Eigen::MatrixXd lower = k.triangularView<Eigen::Lower>();
  return lower.sparseView();
}

double accuracy_of(const CholmodMatrix& lower) {
  SparseCholesky k;
  k.analyze(lower, 1);
  EXPECT_TRUE(k.factorize(lower));
  return solve_accuracy(k, lower);
}

TEST(SolveAccuracy, GrowsWithTheConditionWithinItsBound) {
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double well = accuracy_of(conditioned(30, 10.0, 1));
  const double ill = accuracy_of(conditioned(30, 1e10, 1));
  EXPECT_LE(well, 30 * 10.0 * eps);
  EXPECT_LE(ill, 30 * 1e10 * eps);
  // Far above round-off of a well-conditioned matrix: what the analysis tells a soft mode of
  // the LCP matrix from a mechanism by.
  EXPECT_GT(ill, 1e3 * well);
  EXPECT_GT(ill, 1e-10);
}

}  // namespace
}  // namespace bimrock
