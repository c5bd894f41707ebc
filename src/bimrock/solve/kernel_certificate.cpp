#include <bimrock/solve/kernel_certificate.hpp>

#include <cmath>

#include <Eigen/Cholesky>

#include <bimrock/solve/lcp_columns.hpp>

namespace bimrock {
namespace {

/// The shift and the steps of the inverse iteration that finds a singular block's kernel.
constexpr double kKernelShift = 1e-10;
constexpr int kInverseIterations = 4;

}  // namespace

Eigen::VectorXd kernel_certificate(const Eigen::MatrixXd& a, const Eigen::MatrixXd& m_rows,
                                   const Eigen::VectorXd& q,
                                   const std::vector<Eigen::Index>& rows) {
  const Eigen::Index k = a.rows();
  Eigen::VectorXd s(k);  // symmetric diagonal scaling: rows of M mix units
  for (Eigen::Index i = 0; i < k; ++i)
    s(i) = a(i, i) > 0.0 ? 1.0 / std::sqrt(a(i, i)) : 1.0;
  Eigen::MatrixXd shifted = s.asDiagonal() * (0.5 * (a + a.transpose())) * s.asDiagonal();
  // The eigenvector of the smallest eigenvalue by inverse iteration on the scaled block (unit
  // diagonal) shifted by 1e-10: one factorization, a small fraction of an eigendecomposition.
  // The start, all ones, is not orthogonal to a mechanism's multipliers (all >= 0).
  shifted.diagonal().array() += kKernelShift;
  const Eigen::LDLT<Eigen::MatrixXd> ldlt(shifted);
  if (ldlt.info() != Eigen::Success)
    return {};
  Eigen::VectorXd u = Eigen::VectorXd::Ones(k);
  for (int it = 0; it < kInverseIterations; ++it) {
    u = ldlt.solve(u);
    u /= u.norm();
  }
  if (!u.allFinite())
    return {};
  Eigen::VectorXd v = s.asDiagonal() * u;
  if (v.sum() < 0.0)
    v = -v;
  const double tiny = 1e-8 * v.cwiseAbs().maxCoeff();
  if (!(v.array() >= -tiny).all())
    return {};
  return certified_ray(q, rows, m_rows, v.cwiseMax(0.0));
}

}  // namespace bimrock
