#pragma once
// Increment LCPs in their sparse parts (SplitLcp) for the tangent tests, with the dense matrix
// M = N - C K^-1 Phi of a second method (a dense LDLT of K).
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include <bimrock/solve/reduced_tangent.hpp>

#include "solve/random_lcp.hpp"

namespace bimrock::testing {

using Eigen::MatrixXd;
using Eigen::VectorXd;

// A chain of blocks (6 unknowns each) joined by yield points as the analysis builds them: point
// p between blocks p - 1 and p (block 0 to the ground) has a local strain E (2 x 12), springs
// D, and two yield modes with gradients a (associated flow): C = a D E, Phi = C^T, N = a D a^T.
// K = sum E^T D E plus a stiffness of each block's own: larger than the springs, so M is
// positive definite. With `nonassociated` > 0 the flows are b = a + nonassociated R (R random):
// Phi = (b D E)^T and N = a D b^T, so M is not symmetric (still positive definite for small
// values: a P-matrix, one solution for every q).
struct ChainLcp {
  CholmodMatrix k_lower, c, phi, n;
  SplitLcp split;
  MatrixXd m_dense;
  SparseCholesky k;
};

// With `uncoupled` >= 0, K leaves out the springs of that point, which then couples blocks K
// does not (its C is a tenth of its springs', so that M stays positive definite).
inline void make_chain(int blocks, unsigned seed, ChainLcp& out, int uncoupled = -1,
                       double nonassociated = 0.0) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> stiffness(1.0, 3.0);
  const int dofs = 6 * blocks;
  const int rows = 2 * blocks;
  MatrixXd k = MatrixXd::Zero(dofs, dofs);
  MatrixXd c = MatrixXd::Zero(rows, dofs);
  MatrixXd n = MatrixXd::Zero(rows, rows);
  MatrixXd phi = MatrixXd::Zero(dofs, rows);
  for (int b = 0; b < blocks; ++b)
    k.block(6 * b, 6 * b, 6, 6) += random_spd(6, rng);
  for (int p = 0; p < blocks; ++p) {
    const int first = p == 0 ? 0 : 6 * (p - 1);
    const int width = p == 0 ? 6 : 12;
    const MatrixXd e = random_matrix(2, width, rng);
    const Eigen::Vector2d d(stiffness(rng), stiffness(rng));
    const MatrixXd a = random_matrix(2, 2, rng) + 2.0 * MatrixXd::Identity(2, 2);
    const MatrixXd b =
        nonassociated > 0.0 ? MatrixXd(a + nonassociated * random_matrix(2, 2, rng)) : a;
    if (p != uncoupled)
      k.block(first, first, width, width) += e.transpose() * d.asDiagonal() * e;
    c.block(2 * p, first, 2, width) = (p == uncoupled ? 0.1 : 1.0) * a * d.asDiagonal() * e;
    n.block(2 * p, 2 * p, 2, 2) = a * d.asDiagonal() * b.transpose();
    phi.block(first, 2 * p, width, 2) =
        (p == uncoupled ? 0.1 : 1.0) * (b * d.asDiagonal() * e).transpose();
  }
  out.k_lower = k.triangularView<Eigen::Lower>().toDenseMatrix().sparseView();
  out.c = c.sparseView();
  out.phi = phi.sparseView();
  out.n = n.sparseView();
  out.m_dense = n - c * k.ldlt().solve(phi);
  out.split = SplitLcp{&out.k_lower, &out.c, &out.phi, &out.n, random_vector(rows, rng), {}, {}};
  for (int r = 0; r < rows; ++r) {
    out.split.group.push_back(r / 2);
    out.split.group_rank.push_back(2);
  }
  out.k.analyze(out.k_lower, 6);
  ASSERT_TRUE(out.k.factorize(out.k_lower));
}

// A chain whose flows are not its yield functions' gradients: M is not symmetric, but positive
// definite (x.M x > 0 for x != 0), so a P-matrix with one solution for every q.
inline void make_nonassociated_chain(int blocks, unsigned seed, ChainLcp& chain) {
  make_chain(blocks, seed, chain, -1, 0.02);
  const MatrixXd sym = 0.5 * (chain.m_dense + chain.m_dense.transpose());
  ASSERT_GT((chain.m_dense - chain.m_dense.transpose()).cwiseAbs().maxCoeff(),
            1e-3 * chain.m_dense.cwiseAbs().maxCoeff());
  ASSERT_GT(Eigen::SelfAdjointEigenSolver<MatrixXd>(sym).eigenvalues().minCoeff(), 0.0);
}

// The second method: (M_AA + D) z_A = -q_A + D center_A with D = factor N_rr (no damping:
// M_AA z_A = -q_A), formed densely and solved by LU; z = 0 off A.
inline VectorXd dense_solution(const MatrixXd& m_dense, const CholmodMatrix& n, const VectorXd& q,
                               const std::vector<Eigen::Index>& active,
                               const ActiveSetEquations::Damping& damping) {
  const auto k = static_cast<Eigen::Index>(active.size());
  MatrixXd a(k, k);
  VectorXd rhs(k);
  for (Eigen::Index i = 0; i < k; ++i) {
    for (Eigen::Index j = 0; j < k; ++j)
      a(i, j) = m_dense(active[i], active[j]);
    rhs(i) = -q(active[i]);
    if (damping.factor.size() > 0) {
      const double d = damping.factor(i) * n.coeff(active[i], active[i]);
      a(i, i) += d;
      rhs(i) += d * damping.center(active[i]);
    }
  }
  const VectorXd za = a.partialPivLu().solve(rhs);
  VectorXd z = VectorXd::Zero(q.size());
  for (Eigen::Index i = 0; i < k; ++i)
    z(active[i]) = za(i);
  return z;
}

inline VectorXd dense_solution(const ChainLcp& chain, const std::vector<Eigen::Index>& active,
                               const ActiveSetEquations::Damping& damping) {
  return dense_solution(chain.m_dense, chain.n, chain.split.q, active, damping);
}

// The tangent S - Phi_A N_AA^-1 C_A of the rows `active`, formed densely.
inline MatrixXd dense_tangent(const ChainLcp& chain, const std::vector<Eigen::Index>& active) {
  const MatrixXd k = MatrixXd(chain.k_lower).selfadjointView<Eigen::Lower>();
  const auto a = static_cast<Eigen::Index>(active.size());
  MatrixXd phi(k.rows(), a);
  MatrixXd c(a, k.rows());
  MatrixXd n(a, a);
  for (Eigen::Index i = 0; i < a; ++i) {
    phi.col(i) = MatrixXd(chain.phi).col(active[i]);
    c.row(i) = MatrixXd(chain.c).row(active[i]);
    for (Eigen::Index j = 0; j < a; ++j)
      n(i, j) = chain.n.coeff(active[i], active[j]);
  }
  return k - phi * n.inverse() * c;
}

// Rows first, first + step, ... below size: an active set.
inline std::vector<Eigen::Index> every(Eigen::Index step, Eigen::Index size,
                                       Eigen::Index first = 0) {
  std::vector<Eigen::Index> rows;
  for (Eigen::Index r = first; r < size; r += step)
    rows.push_back(r);
  return rows;
}

}  // namespace bimrock::testing
