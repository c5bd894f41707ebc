// Joint trace generation. Counts are worked by hand from the documented coverage: the box
// grown by trace_margin = 0.02 * diagonal + spacing on every side, joint k at offset k * spacing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/joint_set.hpp>

namespace bimrock {
namespace {

BBox box_of(double x0, double y0, double x1, double y1) {
  BBox b;
  b.add(Vec2(x0, y0));
  b.add(Vec2(x1, y1));
  return b;
}

std::vector<double> coordinates(const std::vector<JointTrace>& traces) {
  std::vector<double> c;
  for (const JointTrace& t : traces)
    c.insert(c.end(), {t.segment.a.x(), t.segment.a.y(), t.segment.b.x(), t.segment.b.y()});
  return c;
}

bool same_bytes(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(JointSet, PersistentSetCoversTheGrownBox) {
  // Box [0,10]^2: margin = 0.02 * sqrt(200) + 1 = 1.283, so joints y = k lie in
  // [-1.283, 11.283]: k = -1 .. 11, 13 traces, each spanning the grown box in x.
  JointSet s{.material = "bedding", .dip_deg = 0.0, .spacing = 1.0};
  const auto traces = generate_traces(s, 0, box_of(0, 0, 10, 10));
  const double m = 0.02 * std::sqrt(200.0) + 1.0;
  EXPECT_DOUBLE_EQ(trace_margin(box_of(0, 0, 10, 10), s), m);
  ASSERT_EQ(traces.size(), 13u);
  for (const JointTrace& t : traces) {
    EXPECT_EQ(t.segment.a.y(), t.segment.b.y());  // exactly horizontal
    EXPECT_NEAR(t.segment.length(), 10.0 + 2.0 * m, 1e-12);
    EXPECT_EQ(t.material, "bedding");
    EXPECT_EQ(t.set, 0);
    EXPECT_EQ(t.segment.a.y(), t.joint);
  }
}

TEST(JointSet, NinetyDegreesIsExactlyVertical) {
  EXPECT_EQ(direction_deg(90.0), Vec2(0.0, 1.0));
  EXPECT_EQ(direction_deg(-90.0), Vec2(0.0, -1.0));
  EXPECT_EQ(direction_deg(450.0), Vec2(0.0, 1.0));
  JointSet s{.dip_deg = 90.0, .spacing = 2.0};
  for (const JointTrace& t : generate_traces(s, 0, box_of(0, 0, 10, 10)))
    EXPECT_EQ(t.segment.a.x(), t.segment.b.x());
}

TEST(JointSet, TracesAndGapsAlternateAlongEachJoint) {
  // Joint 0 (y = 0) through the box [0,20] x [-0.1,0.1], grown by m = 0.02 * 20.001 + 5 to
  // x in [-m, 20 + m] = [-5.40002, 25.40002]. Traces of 3 with gaps of 2 (period 5) occupy
  // [5j, 5j + 3]: j = -2 ([-10,-7]) misses, j = -1 .. 5 hit, the last one clipped at 20 + m.
  JointSet s{.dip_deg = 0.0, .spacing = 5.0, .trace_length = 3.0, .gap = 2.0};
  const BBox box = box_of(0, -0.1, 20, 0.1);
  const double m = trace_margin(box, s);
  std::vector<JointTrace> on_zero;
  for (const JointTrace& t : generate_traces(s, 0, box))
    if (t.joint == 0)
      on_zero.push_back(t);
  ASSERT_EQ(on_zero.size(), 7u);
  EXPECT_EQ(on_zero.front().segment.a.x(), -5.0);
  EXPECT_EQ(on_zero.front().segment.b.x(), -2.0);
  EXPECT_EQ(on_zero[3].segment.a.x(), 10.0);
  EXPECT_EQ(on_zero.back().segment.a.x(), 25.0);
  EXPECT_DOUBLE_EQ(on_zero.back().segment.b.x(), 20.0 + m);
}

TEST(JointSet, StaggeredJointsShiftByHalfAPeriod) {
  // Vertical joints x = -2k (normal (-1, 0)), traces of 1 with gaps of 1 (period 2): even
  // joints hold [2j, 2j+1] in y, odd ones [2j+1, 2j+2], as the head joints of a brick wall.
  JointSet s{.dip_deg = 90.0, .spacing = 2.0, .trace_length = 1.0, .gap = 1.0, .staggered = true};
  for (const JointTrace& t : generate_traces(s, 0, box_of(0, 0, 8, 4))) {
    EXPECT_DOUBLE_EQ(t.segment.a.x(), -2.0 * t.joint);
    const double start = t.segment.a.y() - (t.joint % 2 != 0 ? 1.0 : 0.0);
    // A trace starts at an even (odd) y unless the grown box clipped it.
    if (t.segment.length() == 1.0) {
      EXPECT_EQ(std::fmod(start + 100.0, 2.0), 0.0) << t.joint;
    }
  }
}

JointSet varied_set(std::uint64_t seed, Distribution d) {
  return {.material = "j",
          .dip_deg = 30.0,
          .spacing = 0.5,
          .origin = {1.0, 2.0},
          .trace_length = 2.0,
          .gap = 1.0,
          .staggered = true,
          .spacing_variation = {d, 0.1},
          .dip_variation = {d, 5.0},
          .seed = seed};
}

TEST(JointSet, SameSeedGivesByteIdenticalTraces) {
  for (Distribution d : {Distribution::uniform, Distribution::normal}) {
    const auto a = coordinates(generate_traces(varied_set(7, d), 0, box_of(0, 0, 20, 10)));
    const auto b = coordinates(generate_traces(varied_set(7, d), 0, box_of(0, 0, 20, 10)));
    const auto c = coordinates(generate_traces(varied_set(8, d), 0, box_of(0, 0, 20, 10)));
    EXPECT_TRUE(same_bytes(a, b));
    EXPECT_FALSE(same_bytes(a, c));
  }
}

TEST(JointSet, SpacingVariationHasTheGivenMeanAndSpread) {
  // Horizontal persistent joints over 2000 m: the mean spacing of ~4000 draws is 0.5 within
  // 4 standard errors (0.1 / sqrt(4000) = 0.0016), and their spread is 0.1 within 5%.
  JointSet s{
      .dip_deg = 0.0, .spacing = 0.5, .spacing_variation = {Distribution::normal, 0.1}, .seed = 3};
  const auto traces = generate_traces(s, 0, box_of(0, 0, 1, 2000));
  std::vector<double> y;
  for (const JointTrace& t : traces)
    y.push_back(t.segment.a.y());
  std::sort(y.begin(), y.end());
  double sum = 0.0;
  double sum2 = 0.0;
  const auto n = static_cast<double>(y.size() - 1);
  for (std::size_t k = 1; k < y.size(); ++k) {
    sum += y[k] - y[k - 1];
    sum2 += (y[k] - y[k - 1]) * (y[k] - y[k - 1]);
  }
  const double mean = sum / n;
  EXPECT_NEAR(mean, 0.5, 4 * 0.1 / std::sqrt(n));
  EXPECT_NEAR(std::sqrt(sum2 / n - mean * mean), 0.1, 0.005);
}

TEST(JointSet, BadParametersNameTheField) {
  const auto field_of = [](const JointSet& s) {
    try {
      const std::vector<JointSet> sets{JointSet{}, s};
      generate_traces(sets, {}, box_of(0, 0, 1, 1));
    } catch (const GeometryError& e) {
      return e.item();
    }
    return std::string("valid");
  };
  EXPECT_EQ(field_of({.spacing = 0.0}), "joint_sets[1].spacing");
  EXPECT_EQ(field_of({.spacing = -1.0}), "joint_sets[1].spacing");
  EXPECT_EQ(field_of({.trace_length = 0.0}), "joint_sets[1].trace_length");
  EXPECT_EQ(field_of({.gap = -1.0}), "joint_sets[1].gap");
  EXPECT_EQ(field_of({.dip_variation = {Distribution::normal, -1.0}}),
            "joint_sets[1].dip_variation");
  EXPECT_EQ(field_of({.spacing = 1e-9}), "joint_sets[1]");  // far too many joints
}

TEST(JointSet, IndividualJointsFollowTheSets) {
  const std::vector<JointSet> sets{{.material = "a", .spacing = 10.0}};
  const std::vector<Joint> joints{{"fault", {{0, 0}, {1, 1}}}};
  const auto traces = generate_traces(sets, joints, box_of(0, 0, 1, 1));
  ASSERT_FALSE(traces.empty());
  EXPECT_EQ(traces.back().set, -1);
  EXPECT_EQ(traces.back().joint, 0);
  EXPECT_EQ(traces.back().material, "fault");
}

TEST(JointSet, SuggestedSliverAreaIsOnePercentOfTheSmallestSpacingSquared) {
  const std::vector<JointSet> sets{{.spacing = 2.0}, {.spacing = 0.5}};
  EXPECT_DOUBLE_EQ(suggested_min_block_area(sets), 0.0025);
}

}  // namespace
}  // namespace bimrock
