#include <bimrock/solve/condensed_stiffness.hpp>

#include <algorithm>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace bimrock {

namespace {
constexpr int kBlock = 6;  // unknowns per block

// Every block's neighbours across interfaces (supports excluded).
std::vector<std::vector<int>> neighbours(const Model& model) {
  std::vector<std::vector<int>> out(static_cast<std::size_t>(model.n_blocks()));
  for (const Interface& i : model.interfaces)
    if (!i.is_support()) {
      out[static_cast<std::size_t>(i.block_i)].push_back(i.block_j);
      out[static_cast<std::size_t>(i.block_j)].push_back(i.block_i);
    }
  return out;
}
}  // namespace

CondensedStiffness::CondensedStiffness(const SpdSolver& k, const SparseMatrix& k_lower)
    : blocks_(static_cast<std::size_t>(k_lower.rows() / kBlock)), lower_(&k_lower), factor_(&k) {
  std::iota(blocks_.begin(), blocks_.end(), 0);
}

CondensedStiffness::CondensedStiffness(const std::vector<char>& region, SparseMatrix s_lower)
    : zone_(region), own_lower_(std::move(s_lower)) {
  for (std::size_t b = 0; b < zone_.size(); ++b)
    if (zone_[b])
      blocks_.push_back(static_cast<int>(b));
  const auto n = static_cast<std::int64_t>(kBlock * blocks_.size());
  if (own_lower_.rows() != n || own_lower_.cols() != n)
    throw std::logic_error("CondensedStiffness: S is not of the region's size");
  std::vector<Eigen::Triplet<double, std::int64_t>> ones;
  ones.reserve(static_cast<std::size_t>(n));
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    for (int d = 0; d < kBlock; ++d)
      ones.emplace_back(kBlock * static_cast<std::int64_t>(blocks_[k]) + d,
                        kBlock * static_cast<std::int64_t>(k) + d, 1.0);
  select_.resize(kBlock * static_cast<std::int64_t>(zone_.size()), n);
  select_.setFromTriplets(ones.begin(), ones.end());
  lower_ = &own_lower_;
}

CondensedStiffness::CondensedStiffness(const CondensedStiffness& base, const SparseCholesky& factor,
                                       int level, bool solvable)
    : zone_(base.whole() ? base.blocks_.size() : base.zone_.size(), 0) {
  if (factor.rows() != base.lower().rows())
    throw std::logic_error("CondensedStiffness: the factor is not of the base's S");
  own_lower_ = factor.schur_complement(base.lower(), level);
  // The unknowns of S among base's, then among K's.
  const std::vector<std::int64_t> unknowns = factor.trailing_unknowns(level);
  for (std::size_t j = 0; j < unknowns.size(); j += kBlock)
    blocks_.push_back(base.blocks_[static_cast<std::size_t>(unknowns[j] / kBlock)]);
  for (int b : blocks_)
    zone_[static_cast<std::size_t>(b)] = 1;
  std::vector<Eigen::Triplet<double, std::int64_t>> ones;
  ones.reserve(unknowns.size());
  for (std::size_t j = 0; j < unknowns.size(); ++j) {
    // Column unknowns[j] of base's selection (one 1 in each), or the unknown itself for K.
    const std::int64_t u =
        base.whole() ? unknowns[j]
                     : base.select_.innerIndexPtr()[base.select_.outerIndexPtr()[unknowns[j]]];
    ones.emplace_back(u, static_cast<std::int64_t>(j), 1.0);
  }
  const std::int64_t n = base.whole() ? base.lower().rows() : base.select_.rows();
  select_.resize(n, static_cast<Eigen::Index>(unknowns.size()));
  select_.setFromTriplets(ones.begin(), ones.end());
  lower_ = &own_lower_;
  if (solvable) {
    // The trailing block of base's factor is a factor of S: no factorization of its own (one
    // was 20 MB and 0.01-0.05 s per zone at 10^4 blocks).
    schur_solver_ = std::make_unique<SchurSolver>(factor, level);
    factor_ = schur_solver_.get();
  }
}

const SpdSolver& CondensedStiffness::factor() const {
  if (!factor_)
    throw std::logic_error("CondensedStiffness: a region's S is not solved with");
  return *factor_;
}

std::vector<char> CondensedStiffness::on_blocks(const std::vector<char>& per_model_block) const {
  std::vector<char> out(blocks_.size());
  for (std::size_t k = 0; k < blocks_.size(); ++k)
    out[k] = per_model_block[static_cast<std::size_t>(blocks_[k])];
  return out;
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

std::vector<char> grow_zone(const Model& model, std::vector<char> zone, int target,
                            const std::vector<char>* within, int rings) {
  const std::vector<std::vector<int>> next_to = neighbours(model);
  std::vector<int> ring;
  for (int b = 0; b < model.n_blocks(); ++b)
    if (zone[static_cast<std::size_t>(b)])
      ring.push_back(b);
  auto count = static_cast<int>(ring.size());
  for (int added = 0; added < rings && count < target && !ring.empty(); ++added) {
    std::vector<int> next;
    for (int b : ring)
      for (int n : next_to[static_cast<std::size_t>(b)]) {
        const auto i = static_cast<std::size_t>(n);
        if (!zone[i] && (!within || (*within)[i])) {
          zone[i] = 1;
          next.push_back(n);
        }
      }
    count += static_cast<int>(next.size());
    ring = std::move(next);
  }
  return zone;
}

std::vector<char> interior(const Model& model, const std::vector<char>& region) {
  std::vector<char> out = region;
  for (const Interface& i : model.interfaces) {
    if (i.is_support())
      continue;
    const auto a = static_cast<std::size_t>(i.block_i);
    const auto b = static_cast<std::size_t>(i.block_j);
    if (region[a] != region[b])
      out[a] = out[b] = 0;
  }
  return out;
}

void nest_levels(const Model& model, std::vector<char>& levels) {
  // Relaxation over the interfaces until nothing changes: each pass settles at least the blocks
  // one ring further from the lowest levels, and levels are a few at most.
  for (bool changed = true; changed;) {
    changed = false;
    for (const Interface& i : model.interfaces) {
      if (i.is_support())
        continue;
      char& a = levels[static_cast<std::size_t>(i.block_i)];
      char& b = levels[static_cast<std::size_t>(i.block_j)];
      if (a > b + 1) {
        a = static_cast<char>(b + 1);
        changed = true;
      } else if (b > a + 1) {
        b = static_cast<char>(a + 1);
        changed = true;
      }
    }
  }
}

}  // namespace bimrock
