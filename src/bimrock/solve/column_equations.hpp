#pragma once
/// @file The active-set equations of an LCP given column by column (LcpColumns): the columns of
/// the active rows are asked for once each (kept for later iterations) and the dense active block
/// is solved by Cholesky (symmetric M) or LU; a singular block of a symmetric M is tested as the
/// mechanism of a collapse (kernel_certificate.hpp). The representation ActiveSetLcp uses for
/// a dense LcpProblem or an LcpColumns.
#include <vector>

#include <Eigen/Core>

#include <bimrock/solve/active_set_lcp.hpp>
#include <bimrock/solve/lcp_columns.hpp>

namespace bimrock {

class ColumnEquations final : public ActiveSetEquations {
 public:
  ColumnEquations(LcpColumns& problem, double singular_tolerance)
      : problem_(problem),
        singular_tolerance_(singular_tolerance),
        slot_(static_cast<std::size_t>(problem.size()), -1),
        known_(problem.size(), 0) {}
  [[nodiscard]] Eigen::Index size() const override { return problem_.size(); }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return problem_.q(); }
  [[nodiscard]] Eigen::Index group(Eigen::Index row) const override { return problem_.group(row); }
  [[nodiscard]] int group_rank(Eigen::Index row) const override { return problem_.group_rank(row); }
  [[nodiscard]] bool symmetric() const override { return problem_.symmetric(); }

  using ActiveSetEquations::solve;
  /// w is exact for the columns known, whatever the check asked for.
  Solution solve(const std::vector<Eigen::Index>& rows, const Damping& damping,
                 Check check) override;

  /// Any z: the columns of its support are asked for if not known yet.
  LcpResult result(LcpStatus status, Eigen::VectorXd z, int steps) override;

 private:
  /// Asks for the columns of `rows` not known yet: column slot_[i] of known_ is column i of M.
  void fetch(const std::vector<Eigen::Index>& rows);

  LcpColumns& problem_;
  double singular_tolerance_;
  std::vector<Eigen::Index> slot_;
  Eigen::MatrixXd known_;
};

}  // namespace bimrock
