#pragma once
/// @file Joint sets and their traces in the 2D section. A set is a family of parallel joints at a
/// mean spacing; each joint is a line of traces of length L separated by rock bridges (gaps) of
/// length G. Individual joints are given as segments. Traces carry their joint material.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <bimrock/geometry/bbox.hpp>
#include <bimrock/geometry/segment.hpp>

namespace bimrock {

enum class Distribution {
  none,     ///< no variation
  uniform,  ///< value + U(-amount, +amount)
  normal,   ///< value + N(0, amount^2): `amount` is the standard deviation
};

/// Random variation of one parameter, drawn independently for every joint of the set.
struct Variation {
  Distribution distribution = Distribution::none;
  double amount = 0.0;  ///< half-width (uniform) or standard deviation (normal), >= 0
};

struct JointSet {
  std::string material{};  ///< the joint material of every trace of the set
  /// Direction of the traces, degrees counter-clockwise from +x. Multiples of 90 give exactly
  /// axis-parallel traces (no cos(90 deg) = 6e-17 tilt).
  double dip_deg = 0.0;
  /// Mean distance between successive joints, measured along the normal n = perp(direction).
  double spacing = 1.0;
  /// A point of joint 0; joint k lies at offset (k * spacing) n from it, and the trace pattern
  /// of every joint starts at its foot point (origin + offset n).
  Vec2 origin = Vec2::Zero();
  /// Persistence: traces of this length alternate with gaps of `gap` along each joint. The set
  /// is fully persistent (one trace per joint) when trace_length is absent or gap is 0.
  std::optional<double> trace_length{};
  double gap = 0.0;
  /// Brick pattern: odd joints shift their trace pattern by half a period (L + G) / 2.
  bool staggered = false;
  /// Each spacing (metres) and each joint's dip (degrees) vary about the mean. Spacings below
  /// spacing / 10 are drawn again (a truncated distribution: joints never cross by construction;
  /// with a dip variation they may, as real joints do).
  Variation spacing_variation{};
  Variation dip_variation{};
  std::uint64_t seed = 0;  ///< same seed, same traces (byte for byte)
};

/// A joint given by its trace.
struct Joint {
  std::string material{};
  Segment segment{};
};

/// One straight joint trace and where it came from.
struct JointTrace {
  Segment segment{};
  int set = -1;   ///< index of its joint set, -1 for an individual joint
  int joint = 0;  ///< index of its joint within the set (any sign), or of the individual joint
  std::string material{};
};

/// Throws GeometryError naming `item`.field (e.g. "joint_sets[1].spacing") for a non-positive or
/// non-finite spacing, a non-positive trace length, a negative gap or variation amount.
void validate(const JointSet& set, const std::string& item);

/// Traces of one set covering `box` grown by margin(box, set) on every side, so that
/// persistent traces cross a domain outline inscribed in `box` cleanly instead of ending on it.
/// Joints whose foot point lies outside the grown box are skipped (with a dip variation, a
/// tilted joint near a corner may be missed: give the box some room).
std::vector<JointTrace> generate_traces(const JointSet& set, int set_index, const BBox& box);

/// All traces: every set in order (set index = position in `sets`), then the individual joints
/// (joint index = position in `joints`). Validates the sets first.
std::vector<JointTrace> generate_traces(std::span<const JointSet> sets,
                                        std::span<const Joint> joints, const BBox& box);

/// The growth of `box` used by generate_traces: 2% of its diagonal plus one spacing, or plus the
/// diagonal when the spacing is larger (a larger margin would only hold traces far outside the
/// box, and their number grows with it).
double trace_margin(const BBox& box, const JointSet& set);

/// What generate_traces(set, _, box) would produce, estimated without generating: the number
/// of traces (an upper bound with constant spacing) and their total length. Never overflows:
/// huge counts are returned as huge doubles.
struct TraceEstimate {
  double traces = 0.0;
  double length = 0.0;
};
TraceEstimate estimate_traces(const JointSet& set, const BBox& box);

/// Unit vector at `deg` degrees counter-clockwise from +x, exact at multiples of 90 degrees.
Vec2 direction_deg(double deg);

/// A sliver threshold for the block cutter: 1% of the smallest spacing squared (0 without sets).
double suggested_min_block_area(std::span<const JointSet> sets);

}  // namespace bimrock
