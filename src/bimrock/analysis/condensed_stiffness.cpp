#include <bimrock/analysis/condensed_stiffness.hpp>

#include <algorithm>
#include <stdexcept>

namespace bimrock {

namespace {
constexpr int kBlock = 6;  // unknowns per block
}  // namespace

CondensedStiffness::CondensedStiffness(const SparseCholesky& k, const SparseMatrix& k_lower)
    : lower_(&k_lower), factor_(&k) {}

CondensedStiffness::CondensedStiffness(const SparseCholesky& k, const SparseMatrix& k_lower,
                                       const std::vector<char>& levels, int level)
    : zone_(levels.size(), 0), own_factor_(std::make_unique<SparseCholesky>()) {
  for (std::size_t b = 0; b < levels.size(); ++b)
    zone_[b] = levels[b] >= level ? 1 : 0;
  own_lower_ = k.schur_complement(k_lower, level);
  const std::vector<std::int64_t> unknowns = k.trailing_unknowns(level);
  std::vector<Eigen::Triplet<double, std::int64_t>> ones;
  ones.reserve(unknowns.size());
  for (std::size_t j = 0; j < unknowns.size(); ++j)
    ones.emplace_back(unknowns[j], static_cast<std::int64_t>(j), 1.0);
  select_.resize(k_lower.rows(), static_cast<Eigen::Index>(unknowns.size()));
  select_.setFromTriplets(ones.begin(), ones.end());
  own_factor_->analyze(own_lower_, kBlock);
  // S is positive definite where K is (a Schur complement of it): a failure is round-off in a
  // nearly singular K, reported by factorized() (the caller goes on with K itself).
  factorized_ = own_factor_->factorize(own_lower_);
  lower_ = &own_lower_;
  factor_ = own_factor_.get();
}

int CondensedStiffness::zone_blocks() const {
  return whole() ? static_cast<int>(lower_->rows() / kBlock)
                 : static_cast<int>(std::count(zone_.begin(), zone_.end(), 1));
}

YieldSystem CondensedStiffness::local(const YieldSystem& sys) const {
  if (whole())
    return sys;
  YieldSystem out;
  out.rows = sys.rows;
  out.c = sys.c * select_;
  out.phi = SparseMatrix(select_.transpose()) * sys.phi;
  if (out.c.nonZeros() != sys.c.nonZeros() || out.phi.nonZeros() != sys.phi.nonZeros())
    throw std::logic_error("CondensedStiffness: a yield row touches a block outside the zone");
  out.n = sys.n;
  out.f0 = sys.f0;
  out.flow = sys.flow;
  return out;
}

Eigen::VectorXd CondensedStiffness::local(const Eigen::VectorXd& v) const {
  if (whole())
    return v;
  return select_.transpose() * v;
}

std::vector<char> grow_zone(const Model& model, std::vector<char> zone, int target) {
  std::vector<std::vector<int>> neighbours(static_cast<std::size_t>(model.n_blocks()));
  for (const Interface& i : model.interfaces)
    if (!i.is_support()) {
      neighbours[static_cast<std::size_t>(i.block_i)].push_back(i.block_j);
      neighbours[static_cast<std::size_t>(i.block_j)].push_back(i.block_i);
    }
  std::vector<int> ring;
  for (int b = 0; b < model.n_blocks(); ++b)
    if (zone[static_cast<std::size_t>(b)])
      ring.push_back(b);
  auto count = static_cast<int>(ring.size());
  while (count < target && !ring.empty()) {
    std::vector<int> next;
    for (int b : ring)
      for (int n : neighbours[static_cast<std::size_t>(b)])
        if (!zone[static_cast<std::size_t>(n)]) {
          zone[static_cast<std::size_t>(n)] = 1;
          next.push_back(n);
        }
    count += static_cast<int>(next.size());
    ring = std::move(next);
  }
  return zone;
}

}  // namespace bimrock
