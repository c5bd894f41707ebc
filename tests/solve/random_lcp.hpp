#pragma once
// Random LCPs with fixed seeds for the solver tests. Their expected solutions never come from
// here: they come from enumeration, from a planted solution, or from hand calculation.
#include <random>

#include <Eigen/Core>

#include <bimrock/solve/lcp.hpp>

namespace bimrock::testing {

inline Eigen::MatrixXd random_matrix(Eigen::Index rows, Eigen::Index cols, std::mt19937& rng) {
  std::normal_distribution<double> normal;
  Eigen::MatrixXd a(rows, cols);
  for (Eigen::Index j = 0; j < cols; ++j) {
    for (Eigen::Index i = 0; i < rows; ++i)
      a(i, j) = normal(rng);
  }
  return a;
}

inline Eigen::VectorXd random_vector(Eigen::Index n, std::mt19937& rng) {
  return random_matrix(n, 1, rng);
}

/// Symmetric positive definite with eigenvalues in about [1, 5]: A^T A / n + I.
inline Eigen::MatrixXd random_spd(Eigen::Index n, std::mt19937& rng) {
  const Eigen::MatrixXd a = random_matrix(n, n, rng);
  return a.transpose() * a / static_cast<double>(n) + Eigen::MatrixXd::Identity(n, n);
}

/// Non-symmetric with a positive, strictly dominant diagonal in every row: every principal
/// submatrix is again so, hence has eigenvalues with positive real part and a positive
/// determinant (Gershgorin): a P-matrix, so the LCP has exactly one solution for every q.
inline Eigen::MatrixXd random_p_matrix(Eigen::Index n, std::mt19937& rng) {
  std::uniform_real_distribution<double> margin(0.1, 1.0);
  Eigen::MatrixXd m = random_matrix(n, n, rng);
  for (Eigen::Index i = 0; i < n; ++i) {
    m(i, i) = 0.0;
    m(i, i) = m.row(i).cwiseAbs().sum() + margin(rng);
  }
  return m;
}

/// Positive definite but far from symmetric: A A^T / n + 0.1 I plus a large skew part
/// 3 (A - A^T), which leaves x^T M x > 0 unchanged: a P-matrix on which the block rule of the
/// active-set method often cycles.
inline Eigen::MatrixXd random_skewed_positive_definite(Eigen::Index n, std::mt19937& rng) {
  const Eigen::MatrixXd a = random_matrix(n, n, rng);
  return a * a.transpose() / static_cast<double>(n) + 0.1 * Eigen::MatrixXd::Identity(n, n) +
         3.0 * (a - a.transpose());
}

/// q = w* - M z* for complementary z*, w* >= 0: the LCP (q, M) has the solution z* by
/// construction.
inline Eigen::VectorXd planted_q(const Eigen::MatrixXd& m, const Eigen::VectorXd& z_star,
                                 const Eigen::VectorXd& w_star) {
  return w_star - m * z_star;
}

}  // namespace bimrock::testing
