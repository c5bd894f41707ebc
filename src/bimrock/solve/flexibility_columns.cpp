#include <bimrock/solve/flexibility_columns.hpp>

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace bimrock {

namespace {
/// Right-hand sides per solve: enough for the blocked (BLAS 3) solve to pay, few enough that
/// the dense n x k right-hand side stays small beside the factor.
constexpr Eigen::Index kBatch = 128;
}  // namespace

FlexibilityColumns::FlexibilityColumns(const SpdSolver& k, std::int64_t budget_bytes)
    : k_(k),
      budget_columns_(
          std::max<std::int64_t>(kBatch, budget_bytes / std::max<std::int64_t>(1, 8 * k.rows()))) {}

std::uint64_t FlexibilityColumns::key(const YieldRow& row) {
  return (static_cast<std::uint64_t>(row.point) << 16) ^ static_cast<std::uint64_t>(row.mode);
}

std::vector<std::pair<std::int64_t, double>> FlexibilityColumns::phi_column(const YieldSystem& sys,
                                                                            Eigen::Index r) {
  std::vector<std::pair<std::int64_t, double>> out;
  for (SparseMatrix::InnerIterator it(sys.phi, r); it; ++it)
    out.emplace_back(it.row(), it.value());
  return out;
}

void FlexibilityColumns::prepare(const YieldSystem& sys, const std::vector<Eigen::Index>& rows) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<Eigen::Index> missing;
  for (Eigen::Index r : rows) {
    const auto found = cache_.find(key(sys.rows[static_cast<std::size_t>(r)]));
    if (found == cache_.end() || found->second.phi != phi_column(sys, r))
      missing.push_back(r);
  }
  if (static_cast<std::int64_t>(cache_.size() + missing.size()) > budget_columns_) {
    cache_.clear();  // rare: then the columns of this call alone are kept
    missing = rows;
  }
  for (std::size_t first = 0; first < missing.size(); first += kBatch) {
    const auto count =
        static_cast<Eigen::Index>(std::min<std::size_t>(kBatch, missing.size() - first));
    Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(k_.rows(), count);
    for (Eigen::Index c = 0; c < count; ++c)
      rhs.col(c) = sys.phi.col(missing[first + static_cast<std::size_t>(c)]);
    const Eigen::MatrixXd y = k_.solve(rhs);
    for (Eigen::Index c = 0; c < count; ++c) {
      const Eigen::Index r = missing[first + static_cast<std::size_t>(c)];
      cache_[key(sys.rows[static_cast<std::size_t>(r)])] = Entry{phi_column(sys, r), y.col(c)};
    }
    solved_ += count;
  }
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

const Eigen::VectorXd& FlexibilityColumns::column(const YieldSystem& sys, Eigen::Index r) const {
  const auto found = cache_.find(key(sys.rows[static_cast<std::size_t>(r)]));
  if (found == cache_.end())
    throw std::logic_error("FlexibilityColumns: column asked for before prepare()");
  return found->second.y;
}

Eigen::VectorXd FlexibilityColumns::combine(const YieldSystem& sys, const Eigen::VectorXd& v) {
  const auto start = std::chrono::steady_clock::now();
  Eigen::VectorXd out = k_.solve(Eigen::VectorXd(sys.phi * v));
  seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace bimrock
