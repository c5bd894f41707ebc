#pragma once
/// @file The Farkas certificate of a singular dense active block of a symmetric LCP: the
/// mechanism of a collapse, found as the block's kernel vector (active_set_lcp.hpp). The sparse
/// route finds its own from the reduced tangent (reduced_tangent.hpp).
#include <vector>

#include <Eigen/Core>

namespace bimrock {

/// A singular active block `a` (the rows and columns `rows` of a symmetric M, whose columns
/// `m_rows` are given) may be the mechanism of a collapse: its kernel vector v, signed to be
/// non-negative and extended by zeros, certifies that the LCP has no solution when also M v <= 0
/// off the active rows and q . v < 0 (Farkas, see lcp.hpp; for symmetric M, M^T v is the active
/// columns times v). Returns the certificate (certified_ray, lcp_columns.hpp) or an empty vector.
[[nodiscard]] Eigen::VectorXd kernel_certificate(const Eigen::MatrixXd& a,
                                                 const Eigen::MatrixXd& m_rows,
                                                 const Eigen::VectorXd& q,
                                                 const std::vector<Eigen::Index>& rows);

}  // namespace bimrock
