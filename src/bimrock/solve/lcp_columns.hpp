#pragma once
/// @file An LCP whose matrix is given column by column. In the analysis M = N - C K^-1 Phi: each
/// column costs a back-solve with the factor of K, so a problem with thousands of candidate rows
/// of which a few hundred become active must never be formed whole. A solver asks only for the
/// columns of the rows it makes active (the implementation may cache them across increments).
#include <vector>

#include <Eigen/Core>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

class LcpColumns {
 public:
  virtual ~LcpColumns() = default;
  [[nodiscard]] virtual Eigen::Index size() const = 0;
  [[nodiscard]] virtual const Eigen::VectorXd& q() const = 0;
  /// The columns `cols` of M, as a size() x cols.size() matrix.
  [[nodiscard]] virtual Eigen::MatrixXd columns(const std::vector<Eigen::Index>& cols) = 0;
  /// Whether M is symmetric (to round-off): then the columns of a set of rows are also their
  /// rows, and M^T r can be formed from the columns of the support of r.
  [[nodiscard]] virtual bool symmetric() const { return false; }
  /// Rows that belong together (the modes of one yield point): at most group_rank(row) rows of
  /// a group can be linearly independent (the dimension of the point's stress space), so an
  /// active set with more of them has a singular block. Default: every row its own group.
  [[nodiscard]] virtual Eigen::Index group(Eigen::Index row) const { return row; }
  [[nodiscard]] virtual int group_rank(Eigen::Index /*row*/) const { return 1; }
};

/// A dense LcpProblem seen column by column.
class DenseLcpColumns final : public LcpColumns {
 public:
  explicit DenseLcpColumns(const LcpProblem& problem)
      : problem_(problem),
        symmetric_((problem.m - problem.m.transpose()).cwiseAbs().maxCoeff() <=
                   1e-12 * problem.m.cwiseAbs().maxCoeff()) {}
  [[nodiscard]] Eigen::Index size() const override { return problem_.size(); }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return problem_.q; }
  [[nodiscard]] Eigen::MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    Eigen::MatrixXd out(problem_.size(), static_cast<Eigen::Index>(cols.size()));
    for (std::size_t k = 0; k < cols.size(); ++k)
      out.col(static_cast<Eigen::Index>(k)) = problem_.m.col(cols[k]);
    return out;
  }
  [[nodiscard]] bool symmetric() const override { return symmetric_; }

 private:
  const LcpProblem& problem_;
  bool symmetric_;
};

/// The result for a z that is zero outside `support`, given the columns of M on the support:
/// w = M_support z_support + q, and the residuals measured as measure() does.
[[nodiscard]] LcpResult make_lcp_result(const Eigen::VectorXd& q,
                                        const std::vector<Eigen::Index>& support,
                                        const Eigen::MatrixXd& support_columns, LcpStatus status,
                                        Eigen::VectorXd z, int steps);

/// For symmetric M: r_support (on the rows `support`, zero elsewhere) as a Farkas certificate
/// of the whole LCP (certifies_infeasibility in lcp.hpp), M^T r being the columns of the support
/// times r_support. Returns the certificate scaled to max 1, or an empty vector if it is none.
[[nodiscard]] Eigen::VectorXd certified_ray(const Eigen::VectorXd& q,
                                            const std::vector<Eigen::Index>& support,
                                            const Eigen::MatrixXd& support_columns,
                                            const Eigen::VectorXd& r_support);

}  // namespace bimrock
