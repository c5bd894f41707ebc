#include <bimrock/solve/stiffness_zones.hpp>

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <utility>

namespace bimrock {
namespace {

/// A new zone has kZoneGrowth times the blocks needed and kZoneRegrowth times the last zone's (a
/// zone outgrown once is outgrown again as the plastic zone spreads); each reserve has
/// kReserveGrowth times the blocks of the zone inside it.
constexpr double kZoneGrowth = 1.5;
constexpr double kZoneRegrowth = 1.2;
constexpr double kReserveGrowth = 1.25;
/// A new region has at least kRegionRegrowth times the blocks of the last one, and none is made
/// that is not kRegionGrowthLeast times the zone's target.
constexpr double kRegionRegrowth = 2.0;
constexpr double kRegionGrowthLeast = 2.0;

int size(const std::vector<char>& flags) {
  return static_cast<int>(std::count(flags.begin(), flags.end(), 1));
}

}  // namespace

StiffnessZones::StiffnessZones(const Model& model, StiffnessFactor& k, const SparseMatrix& k_lower,
                               const ZoneTuning& tuning)
    : model_(model), k_(k), k_lower_(k_lower), tuning_(tuning), whole_k_(k.solver(), k_lower) {}

bool StiffnessZones::covers(const YieldPoint& point) const {
  return condensed_ && condensed_->covers(point.block_i) &&
         (point.block_j == kGround || condensed_->covers(point.block_j));
}

void StiffnessZones::hold(const std::vector<char>& needed) {
  // Few blocks needed and none condensed yet: K itself, until more are needed.
  if (counts_.condensations == 0 && size(needed) <= tuning_.condense_after_blocks) {
    if (!condensed_)
      whole();
    return;
  }
  if (counts_.condensations > 0 && holds(needed, level_))
    return;
  for (int l = level_ - 1; l >= 1 && !levels_.empty(); --l)
    if (holds(needed, l)) {
      retire();
      use(l);
      ++counts_.reserve_switches;
      return;
    }
  const int target =
      std::max({tuning_.least_zone_blocks, static_cast<int>(kZoneGrowth * size(needed)),
                static_cast<int>(kZoneRegrowth * last_zone_)});
  retire();
  const double most = tuning_.condensed_zone_fraction * model_.n_blocks();
  // Inside the region, if it still holds the new zone: where the region's edge cuts the zone's
  // rings, nest_levels() lowers them, and a zone that then misses a needed block asks for a new
  // region.
  int top = 0;
  if (region_) {
    top = plan(needed, target, most);
    if (!holds(needed, top))
      drop_region();
  }
  if (!region_) {
    if (tuning_.region_growth > 0.0)
      make_region(needed, target, std::min(most, tuning_.region_fraction * model_.n_blocks()));
    top = plan(needed, target, most);
    if (region_ && !holds(needed, top)) {  // only where the region was too small for it
      drop_region();
      top = plan(needed, target, most);
    }
  }
  // A zone straight from K needs K's factor in this process. Where it is not (the PETSc
  // backend's), the zone's outermost reserve is condensed as a region and the zone planned inside
  // it.
  if (top > 0 && !region_ && k_.reorderable() == nullptr) {
    std::vector<char> outer(levels_.size(), 0);
    for (std::size_t b = 0; b < levels_.size(); ++b)
      outer[b] = levels_[b] >= 1 ? 1 : 0;
    condense_region(outer);
    top = plan(needed, target, most);
    if (!holds(needed, top)) {
      drop_region();
      top = 0;
    }
  }
  if (top == 0) {
    whole();
  } else {
    const SparseMatrix& s = base().lower();
    base_factor().analyze_last(s, 6, base().on_blocks(levels_));
    if (!base_factor().factorize(s))
      throw std::logic_error("StiffnessZones: K, positive definite before, is not now");
    use(top);
  }
  ++counts_.condensations;
}

// The levels of a new zone of `target` blocks around `needed` and of its reserves (inside the
// region if there is one), nested; the zone's level, or 0 where the zone would be more than
// `most` blocks of K itself (not worth condensing).
int StiffnessZones::plan(const std::vector<char>& needed, int target, double most) {
  const std::vector<char>* within = region_ ? &region_inside_ : nullptr;
  std::vector<char> zone = grow_zone(model_, needed, target, within);
  last_zone_ = size(zone);
  if (!region_ && size(zone) > most)
    return 0;
  // The zone, then its reserves around it (while they are within the fraction): levels counted
  // from the outermost reserve, 1.
  std::vector<std::vector<char>> zones{std::move(zone)};
  for (int r = 0; r < tuning_.zone_reserves; ++r) {
    std::vector<char> outer = grow_zone(
        model_, zones.back(), static_cast<int>(kReserveGrowth * size(zones.back())), within);
    if (size(outer) > most || size(outer) == size(zones.back()))
      break;
    zones.push_back(std::move(outer));
  }
  levels_.assign(needed.size(), 0);
  for (const std::vector<char>& z : zones)
    for (std::size_t b = 0; b < z.size(); ++b)
      levels_[b] = static_cast<char>(levels_[b] + z[b]);
  if (within)  // a needed block off the region's inside stays out, and fails holds()
    for (std::size_t b = 0; b < levels_.size(); ++b)
      levels_[b] = (*within)[b] ? levels_[b] : 0;
  nest_levels(model_, levels_);
  return static_cast<int>(zones.size());
}

// K condensed onto a region around `needed` of region_growth times the zone's target, at least
// kRegionRegrowth times the last region, at most `most` blocks (K factorized with the region
// condensed by its factor); none where that leaves no room for the zone to grow.
void StiffnessZones::make_region(const std::vector<char>& needed, int target, double most) {
  const double wanted = std::max(tuning_.region_growth * target, kRegionRegrowth * last_region_);
  const int blocks = static_cast<int>(std::min(wanted, most));
  if (blocks < kRegionGrowthLeast * target)
    return;
  std::vector<char> r = grow_zone(model_, needed, blocks);
  if (size(r) > most)
    return;
  condense_region(r);
}

void StiffnessZones::condense_region(const std::vector<char>& region) {
  region_ = k_.condense(whole_k_, region);
  // Zones keep off the region's edge, whose blocks its S couples all together.
  region_inside_ = interior(model_, region);
  last_region_ = region_->zone_blocks();
  ++counts_.regions;
}

void StiffnessZones::drop_region() {
  region_.reset();
  region_inside_.clear();
}

// Whether the zone of level `level` (0: the whole model) holds every flagged block.
bool StiffnessZones::holds(const std::vector<char>& needed, int level) const {
  if (level == 0)
    return true;
  for (std::size_t b = 0; b < needed.size(); ++b)
    if (needed[b] && levels_[b] < level)
      return false;
  return true;
}

// Condenses onto zone `level` of the base's factor as it is.
void StiffnessZones::use(int level) {
  level_ = level;
  condensed_ = std::make_unique<CondensedStiffness>(base(), base_factor(), level);
  emplace_solvers();
}

// No condensation: K itself, in its own order (the last zone's is as good for its solves).
void StiffnessZones::whole() {
  level_ = 0;
  levels_.clear();
  condensed_ = std::make_unique<CondensedStiffness>(k_.solver(), k_lower_);
  emplace_solvers();
}

// The work of the solvers that go, for the totals.
void StiffnessZones::retire() {
  if (tangent_)
    retired_tangent_ += tangent_->cholesky.work();
  if (condensed_ && !condensed_->whole())
    retired_s_ += condensed_->factor().work();
  columns_.reset();
  tangent_.reset();
  condensed_.reset();
}

void StiffnessZones::emplace_solvers() {
  // The columns kept may take 12 bytes per entry of S's factor, 1.5 times its values: they set
  // the peak memory of the increments that need them.
  const SpdSolver& s = condensed_->factor();
  columns_.emplace(s, std::max<std::int64_t>(64 << 20, 12 * s.factor_nonzeros()));
  tangent_.emplace();
}

ZoneStatistics StiffnessZones::statistics() const {
  ZoneStatistics s = counts_;
  s.zone_blocks = condensed_ ? condensed_->zone_blocks() : 0;
  s.tangent = retired_tangent_;
  if (tangent_)
    s.tangent += tangent_->cholesky.work();
  s.condensed = retired_s_;
  if (condensed_ && !condensed_->whole())
    s.condensed += condensed_->factor().work();
  return s;
}

}  // namespace bimrock
