#pragma once
// A dense LCP seen column by column that records the columns a solver asks for, to check that
// column-by-column solvers form only the columns they need.
#include <vector>

#include <bimrock/solve/lcp_columns.hpp>

namespace bimrock::testing {

class CountingColumns final : public LcpColumns {
 public:
  explicit CountingColumns(const LcpProblem& p) : dense_(p) {}
  [[nodiscard]] Eigen::Index size() const override { return dense_.size(); }
  [[nodiscard]] const Eigen::VectorXd& q() const override { return dense_.q(); }
  [[nodiscard]] Eigen::MatrixXd columns(const std::vector<Eigen::Index>& cols) override {
    asked.insert(asked.end(), cols.begin(), cols.end());
    return dense_.columns(cols);
  }
  [[nodiscard]] bool symmetric() const override { return dense_.symmetric(); }
  std::vector<Eigen::Index> asked;

 private:
  DenseLcpColumns dense_;
};

}  // namespace bimrock::testing
