#include <bimrock/geometry/joint_set.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/seeded_random.hpp>

namespace bimrock {
namespace {

constexpr double kMaxJointsPerSet = 1e7;  // a guard against a spacing far too small for the box

double vary(SeededRandom& rng, const Variation& v) {
  switch (v.distribution) {
    case Distribution::none:
      return 0.0;
    case Distribution::uniform:
      return rng.uniform(-v.amount, v.amount);
    case Distribution::normal:
      return rng.normal(0.0, v.amount);
  }
  return 0.0;
}

// One spacing, drawn again while below a tenth of the mean (a truncated distribution).
double draw_spacing(SeededRandom& rng, const JointSet& set) {
  for (int attempt = 0; attempt < 100; ++attempt) {
    const double s = set.spacing + vary(rng, set.spacing_variation);
    if (s >= 0.1 * set.spacing)
      return s;
  }
  return 0.1 * set.spacing;
}

// Streams: even numbers for the two walks along the normal, odd ones for each joint's dip, so
// a joint's dip depends on its index only (not on the box or on the spacing variation).
std::uint64_t dip_stream(long k) {
  const auto zigzag = static_cast<std::uint64_t>(k >= 0 ? 2 * k : -2 * k - 1);
  return 2 * zigzag + 1;
}

// Parameter interval [a0, a1] of the line f + a t inside the box; false when it misses.
bool clip_line(const Vec2& f, const Vec2& t, const BBox& box, double& a0, double& a1) {
  a0 = -std::numeric_limits<double>::infinity();
  a1 = std::numeric_limits<double>::infinity();
  for (int axis = 0; axis < 2; ++axis) {
    if (t[axis] == 0.0) {
      if (f[axis] < box.lo[axis] || f[axis] > box.hi[axis])
        return false;
      continue;
    }
    double u = (box.lo[axis] - f[axis]) / t[axis];
    double v = (box.hi[axis] - f[axis]) / t[axis];
    if (u > v)
      std::swap(u, v);
    a0 = std::max(a0, u);
    a1 = std::min(a1, v);
  }
  return a1 > a0;
}

// Offsets (k, o_k) along the normal of every joint whose foot lies in [n_min, n_max].
std::vector<std::pair<long, double>> joint_offsets(const JointSet& set, double n_min, double n_max,
                                                   const std::string& item) {
  const double reach = std::max(std::abs(n_min), std::abs(n_max)) / set.spacing;
  if ((n_max - n_min) / set.spacing > kMaxJointsPerSet || reach > 10 * kMaxJointsPerSet)
    throw GeometryError(item, "the spacing is too small for the region to cover");
  std::vector<std::pair<long, double>> out;
  if (set.spacing_variation.distribution == Distribution::none) {
    const auto k0 = static_cast<long>(std::ceil(n_min / set.spacing));
    const auto k1 = static_cast<long>(std::floor(n_max / set.spacing));
    for (long k = k0; k <= k1; ++k)
      out.emplace_back(k, static_cast<double>(k) * set.spacing);
    return out;
  }
  // Cumulative spacings walk out from joint 0, one stream on each side.
  SeededRandom up(derive_seed(set.seed, 0));
  double o = 0.0;
  for (long k = 0; o <= n_max; ++k) {
    if (o >= n_min)
      out.emplace_back(k, o);
    o += draw_spacing(up, set);
  }
  SeededRandom down(derive_seed(set.seed, 2));
  o = 0.0;
  for (long k = -1;; --k) {
    o -= draw_spacing(down, set);
    if (o < n_min)
      break;
    if (o <= n_max)
      out.emplace_back(k, o);
  }
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace

Vec2 direction_deg(double deg) {
  const double r = std::fmod(deg, 360.0);
  if (r == 0.0)
    return {1.0, 0.0};
  if (r == 90.0 || r == -270.0)
    return {0.0, 1.0};
  if (r == 180.0 || r == -180.0)
    return {-1.0, 0.0};
  if (r == 270.0 || r == -90.0)
    return {0.0, -1.0};
  const double a = deg * M_PI / 180.0;
  return {std::cos(a), std::sin(a)};
}

void validate(const JointSet& set, const std::string& item) {
  if (!std::isfinite(set.dip_deg))
    throw GeometryError(item + ".dip", "must be a finite angle");
  if (!(set.spacing > 0.0) || !std::isfinite(set.spacing))
    throw GeometryError(item + ".spacing", "must be positive");
  if (!std::isfinite(set.origin.x()) || !std::isfinite(set.origin.y()))
    throw GeometryError(item + ".origin", "must be a finite point");
  if (set.trace_length && (!(*set.trace_length > 0.0) || !std::isfinite(*set.trace_length)))
    throw GeometryError(item + ".trace_length", "must be positive");
  if (!(set.gap >= 0.0) || !std::isfinite(set.gap))
    throw GeometryError(item + ".gap", "must be zero or positive");
  if (set.trace_length && !std::isfinite(*set.trace_length + set.gap))
    throw GeometryError(item + ".trace_length", "trace_length + gap must be a finite length");
  if (!(set.spacing_variation.amount >= 0.0) || !std::isfinite(set.spacing_variation.amount))
    throw GeometryError(item + ".spacing_variation", "the amount must be zero or positive");
  if (!(set.dip_variation.amount >= 0.0) || !std::isfinite(set.dip_variation.amount))
    throw GeometryError(item + ".dip_variation", "the amount must be zero or positive");
}

double trace_margin(const BBox& box, const JointSet& set) {
  return 0.02 * box.diagonal() + std::min(set.spacing, box.diagonal());
}

namespace {

BBox grown_box(const BBox& box, const JointSet& set) {
  const double m = trace_margin(box, set);
  BBox grown;
  grown.add(Vec2(box.lo - Vec2(m, m)));
  grown.add(Vec2(box.hi + Vec2(m, m)));
  return grown;
}

// The extent [n_min, n_max] of `grown` along the normal of the set, from its origin.
std::pair<double, double> normal_extent(const BBox& grown, const JointSet& set, const Vec2& n) {
  double n_min = std::numeric_limits<double>::infinity();
  double n_max = -n_min;
  for (const Vec2& c :
       {grown.lo, grown.hi, Vec2(grown.lo.x(), grown.hi.y()), Vec2(grown.hi.x(), grown.lo.y())}) {
    n_min = std::min(n_min, n.dot(c - set.origin));
    n_max = std::max(n_max, n.dot(c - set.origin));
  }
  return {n_min, n_max};
}

}  // namespace

TraceEstimate estimate_traces(const JointSet& set, const BBox& box) {
  if (box.empty())
    return {};
  const BBox grown = grown_box(box, set);
  const auto [n_min, n_max] = normal_extent(grown, set, perp(direction_deg(set.dip_deg)));
  const double joints = std::floor((n_max - n_min) / set.spacing) + 1.0;
  const double reach = grown.diagonal();  // the longest a joint's line is inside `grown`
  const bool persistent = !set.trace_length || set.gap == 0.0;
  if (persistent)
    return {joints, joints * reach};
  const double period = *set.trace_length + set.gap;
  // Whole periods along the line, plus one cut at each end.
  const double per_joint = std::floor(reach / period) + 2.0;
  const double covered = std::min(reach, (reach / period + 1.0) * *set.trace_length);
  return {joints * per_joint, joints * covered};
}

std::vector<JointTrace> generate_traces(const JointSet& set, int set_index, const BBox& box) {
  const std::string item = "joint_sets[" + std::to_string(set_index) + "]";
  validate(set, item);
  std::vector<JointTrace> traces;
  if (box.empty())
    return traces;
  const BBox grown = grown_box(box, set);
  const Vec2 t0 = direction_deg(set.dip_deg);
  const Vec2 n = perp(t0);
  const auto [n_min, n_max] = normal_extent(grown, set, n);
  const bool persistent = !set.trace_length || set.gap == 0.0;
  const double length = persistent ? 0.0 : *set.trace_length;
  const double period = length + set.gap;

  for (const auto& [k, offset] : joint_offsets(set, n_min, n_max, item)) {
    Vec2 t = t0;
    if (set.dip_variation.distribution != Distribution::none) {
      SeededRandom rng(derive_seed(set.seed, dip_stream(k)));
      t = direction_deg(set.dip_deg + vary(rng, set.dip_variation));
    }
    const Vec2 foot = set.origin + offset * n;
    double a0 = 0.0;
    double a1 = 0.0;
    if (!clip_line(foot, t, grown, a0, a1))
      continue;
    // (k copied: clang 14, of the fuzz build, cannot capture a structured binding.)
    const auto add = [&, joint = static_cast<int>(k)](double b0, double b1) {
      traces.push_back({{foot + b0 * t, foot + b1 * t}, set_index, joint, set.material});
    };
    if (persistent) {
      add(a0, a1);
      continue;
    }
    const double phase = (set.staggered && k % 2 != 0) ? 0.5 * period : 0.0;
    // Divided term by term: with a trace length near the largest double, a0 - phase - length
    // overflows to -inf and the trace index with it (a loop from LONG_MIN that never ends).
    const double j0d = std::ceil((a0 - phase) / period - length / period);
    const double j1d = std::floor((a1 - phase) / period);
    if (!(j1d - j0d < kMaxJointsPerSet))
      throw GeometryError(item, "the trace length and gap are too small for the region to cover");
    const auto j0 = static_cast<long>(j0d);
    const auto j1 = static_cast<long>(j1d);
    for (long j = j0; j <= j1; ++j) {
      const double start = phase + static_cast<double>(j) * period;
      const double b0 = std::max(a0, start);
      const double b1 = std::min(a1, start + length);
      if (b1 > b0)
        add(b0, b1);
    }
  }
  return traces;
}

std::vector<JointTrace> generate_traces(std::span<const JointSet> sets,
                                        std::span<const Joint> joints, const BBox& box) {
  std::vector<JointTrace> traces;
  for (std::size_t s = 0; s < sets.size(); ++s) {
    std::vector<JointTrace> t = generate_traces(sets[s], static_cast<int>(s), box);
    traces.insert(traces.end(), std::make_move_iterator(t.begin()),
                  std::make_move_iterator(t.end()));
  }
  for (std::size_t j = 0; j < joints.size(); ++j)
    traces.push_back({joints[j].segment, -1, static_cast<int>(j), joints[j].material});
  return traces;
}

double suggested_min_block_area(std::span<const JointSet> sets) {
  if (sets.empty())
    return 0.0;
  double s = std::numeric_limits<double>::infinity();
  for (const JointSet& set : sets)
    s = std::min(s, set.spacing);
  return 0.01 * s * s;
}

}  // namespace bimrock
