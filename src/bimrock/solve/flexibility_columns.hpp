#pragma once
/// @file The columns K^-1 phi_r of the yield rows: the displacements of a unit plastic multiplier
/// of row r (eq. 23), which make the columns of the LCP matrix M = N - C K^-1 Phi. Each costs a
/// back-solve with the one factor of K, so they are computed only for rows that become active,
/// several at a time (one multi-right-hand-side solve), and kept across rounds and increments:
/// the flow vector phi_r of a yield mode rarely changes (it does when softening turns an
/// associated flow rule), and a kept column is used only while phi_r is exactly the same.
#include <cstdint>
#include <unordered_map>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/yield_system.hpp>
#include <bimrock/solve/spd_solver.hpp>

namespace bimrock {

class FlexibilityColumns {
 public:
  /// @param budget_bytes the columns kept are dropped (all at once) before they would exceed
  ///        this; they are then computed again when needed.
  FlexibilityColumns(const SpdSolver& k, std::int64_t budget_bytes);

  /// Makes the columns of rows `rows` of sys known and current.
  void prepare(const YieldSystem& sys, const std::vector<Eigen::Index>& rows);
  /// K^-1 phi_r for row r of sys; prepare() must have been called for it.
  [[nodiscard]] const Eigen::VectorXd& column(const YieldSystem& sys, Eigen::Index r) const;
  /// sum_r y_r v_r = K^-1 Phi v, by one back-solve (no column is formed or kept).
  [[nodiscard]] Eigen::VectorXd combine(const YieldSystem& sys, const Eigen::VectorXd& v);

  /// Drops every column kept (their memory is returned).
  void clear() { cache_ = {}; }

  [[nodiscard]] std::int64_t solved_columns() const { return solved_; }
  [[nodiscard]] double seconds() const { return seconds_; }

 private:
  struct Entry {
    std::vector<std::pair<std::int64_t, double>> phi;  ///< the column of Phi it was solved for
    Eigen::VectorXd y;
  };
  [[nodiscard]] static std::uint64_t key(const YieldRow& row);
  [[nodiscard]] static std::vector<std::pair<std::int64_t, double>> phi_column(
      const YieldSystem& sys, Eigen::Index r);

  const SpdSolver& k_;
  std::int64_t budget_columns_;
  std::unordered_map<std::uint64_t, Entry> cache_;
  std::int64_t solved_ = 0;
  double seconds_ = 0.0;
};

}  // namespace bimrock
