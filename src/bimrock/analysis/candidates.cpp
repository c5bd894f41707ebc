#include <bimrock/analysis/candidates.hpp>

#include <algorithm>
#include <limits>

#include <bimrock/solve/condensed_stiffness.hpp>  // grow_zone

namespace bimrock {
namespace {

/// Points joining within the margin of yield, at most this many per point that reaches it (or,
/// in a later round, per violated point added): a large step from an unloaded state (a stage's
/// first) brings nearly every point within the margin.
constexpr std::size_t kNearPerReached = 2;

}  // namespace

Candidates::Candidates(const Model& model, const std::vector<YieldPoint>& points,
                       const std::vector<PlasticState>& states, const YieldValues& now,
                       const YieldValues& predicted, double tol, const CandidateTuning& tuning,
                       const std::set<std::pair<int, int>>* flow)
    : model_(model),
      points_(points),
      predicted_(predicted),
      tol_(tol),
      tuning_(tuning),
      candidacy_(points.size(), kNone) {
  // f is linear in the stress for a given plastic state, so f + df is f at U + dU. A point must
  // exceed the tolerance of the final check: a joint that sits exactly on its tension cut-off,
  // as the vertical joints of a free-standing wall do, is not a candidate for its round-off.
  std::size_t reached = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
    if (states[p].gap > 0.0 || predicted.largest(p) > tol) {
      candidacy_[p] = kRequired;
      ++reached;
    }
  join_nearest(predicted, (predicted.f - now.f).cwiseAbs(), kNearPerReached * reached);
  around_ = flow && tuning.near_rings > 0;
  if (around_)
    join_around(*flow);
}

std::vector<char> Candidates::required_blocks() const {
  std::vector<char> blocks(static_cast<std::size_t>(model_.n_blocks()), 0);
  for (std::size_t p = 0; p < candidacy_.size(); ++p)
    if (candidacy_[p] == kRequired)
      flag_blocks(points_[p], blocks);
  return blocks;
}

bool Candidates::in_lcp(std::size_t p, const IncrementSolver& solver) const {
  return candidacy_[p] == kRequired ||
         ((candidacy_[p] == kNear || candidacy_[p] == kAround) && solver.covers(points_[p]));
}

std::vector<int> Candidates::in_lcp(const IncrementSolver& solver) const {
  std::vector<int> out;
  if (std::find(candidacy_.begin(), candidacy_.end(), kRequired) == candidacy_.end())
    return out;
  for (std::size_t p = 0; p < candidacy_.size(); ++p)
    if (in_lcp(p, solver))
      out.push_back(static_cast<int>(p));
  return out;
}

std::size_t Candidates::require(const std::vector<int>& violated, const YieldValues& f,
                                const IncrementSolver& solver) {
  std::size_t outside = 0;
  for (int p : violated) {
    const auto q = static_cast<std::size_t>(p);
    if (!in_lcp(q, solver))
      ++outside;
    candidacy_[q] = kRequired;
  }
  if (outside > 0)
    join_nearest(f, Eigen::VectorXd(f.f - predicted_.f), kNearPerReached * outside);
  return outside;
}

void Candidates::drop_around() {
  std::replace(candidacy_.begin(), candidacy_.end(), static_cast<char>(kAround),
               static_cast<char>(kNone));
  around_ = false;
}

// The points not yet candidates whose yield functions f reach tol within `margin` times their
// change `df` (flat as f; modes where it is positive), nearest first, at most `most`.
void Candidates::join_nearest(const YieldValues& f, const Eigen::VectorXd& df, std::size_t most) {
  std::vector<std::pair<double, std::size_t>> near;  // (margin it needs, point)
  for (std::size_t p = 0; p < candidacy_.size(); ++p) {
    if (candidacy_[p] != kNone)
      continue;
    double needed = std::numeric_limits<double>::infinity();
    for (Eigen::Index i = f.first[p]; i < f.first[p + 1]; ++i)
      if (df(i) > 0.0)
        needed = std::min(needed, (tol_ - f.f(i)) / df(i));
    if (needed < tuning_.margin)
      near.emplace_back(needed, p);
  }
  const std::size_t keep = std::min(near.size(), most);
  std::nth_element(near.begin(), near.begin() + static_cast<std::ptrdiff_t>(keep), near.end());
  for (std::size_t k = 0; k < keep; ++k)
    candidacy_[near[k].second] = kNear;
}

// The points whose blocks lie within near_rings rings of the plastic flow's (the blocks of the
// last increment's active rows and of this step's required points). On the reduced tangent a
// candidate row costs only its share of w = q + N z - C x, and the flow spreads to the
// neighbours of its blocks: one round holds what rounds would add one after another.
void Candidates::join_around(const std::set<std::pair<int, int>>& flow) {
  std::vector<char> blocks = required_blocks();
  for (const auto& [p, mode] : flow)
    flag_blocks(points_[static_cast<std::size_t>(p)], blocks);
  blocks = grow_zone(model_, std::move(blocks), std::numeric_limits<int>::max(), nullptr,
                     tuning_.near_rings);
  for (std::size_t p = 0; p < candidacy_.size(); ++p) {
    const YieldPoint& point = points_[p];
    if (candidacy_[p] == kNone && predicted_.largest(p) > kAbsentPoint &&
        blocks[static_cast<std::size_t>(point.block_i)] &&
        (point.block_j == kGround || blocks[static_cast<std::size_t>(point.block_j)]))
      candidacy_[p] = kAround;
  }
}

}  // namespace bimrock
