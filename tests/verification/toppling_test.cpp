// Verification: block toppling on a stepped base, the factor of safety by strength reduction
// against Goodman & Bray's limit equilibrium method.
//
// Source of the expected numbers: Goodman, R. E. and Bray, J. W. (1976), "Toppling of rock
// slopes", Proc. Specialty Conference on Rock Engineering for Foundations and Slopes, ASCE,
// Boulder, vol. 2, 201-234; as set out in Wyllie & Mah, Rock Slope Engineering, 4th ed. (2004),
// section 7.3, written here for the geometry of the test. The blocks, rectangles of width dx on
// a staircase base whose treads dip at alpha, are drawn in the frame of the treads (gravity tilted
// by alpha, downslope along -x), the same problem turned. From the top block down, each block n
// takes the force P_n of the block above (normal to their common face, at the top of the
// contact, with the friction P_n tan(phi_d) of a block moving down past it) and passes on to the
// block below the larger of the force that stops it toppling about its toe,
//   P_t = (P_n (M_n - dx tan(phi_d)) + W_n / 2 (h_n sin(alpha) - dx cos(alpha))) / L_n,
// and the force that stops it sliding on its base,
//   P_s = P_n - W_n (tan(phi_p) cos(alpha) - sin(alpha)) / (1 - tan(phi_p) tan(phi_d)),
// or nothing where both are negative (a stable block), M_n and L_n the heights on block n of the
// contacts above and below. F divides tan(phi_p) and tan(phi_d) until the force the toe block
// needs, P_0, is zero. The model's interface springs sit at the interfaces' end points, so its
// forces act where Goodman & Bray put them. Goodman & Bray assume each block's mode (pure
// toppling or pure sliding) instead of searching for the weakest: on this staircase (a sliding
// toe block, four toppling blocks) the two agree to 6e-4. With a second sliding block at the toe
// and three stable ones above the crest (heights 1, 2, 3.2, 4, 4.4, 4.2, 3.4, 2.2, 1 m) the
// strength reduction finds F 1.5% lower (1.6038 against 1.6282): a mechanism whose second block
// slides and turns at once, which the method does not consider.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"
#include "support/degrees.hpp"

namespace bimrock {
namespace {

using testing::kDeg;

enum class Mode { stable, topple, slide };

struct Staircase {
  double dx = 1.0;
  double alpha_deg = 15.0;     // dip of the treads
  double phi_base_deg = 30.0;  // the treads' friction angle
  double phi_side_deg = 30.0;  // the joints' between blocks
  double unit_weight = 25e3;
  double rise = 0.25;  // of each step
  std::vector<double> heights = {2.0, 3.2, 4.0, 4.4, 4.2};

  [[nodiscard]] int n() const { return static_cast<int>(heights.size()); }
  [[nodiscard]] double base(int k) const { return k * rise; }  // block k from the toe, 0-based
  [[nodiscard]] double top(int k) const { return base(k) + heights[k]; }
};

struct GoodmanBray {
  double p0 = 0.0;          // the force the toe block needs [N per m]
  std::vector<Mode> modes;  // from the toe
};

GoodmanBray goodman_bray(const Staircase& s, double factor) {
  const double a = s.alpha_deg * kDeg;
  const double tan_p = std::tan(s.phi_base_deg * kDeg) / factor;
  const double tan_d = std::tan(s.phi_side_deg * kDeg) / factor;
  GoodmanBray out;
  out.modes.assign(static_cast<std::size_t>(s.n()), Mode::stable);
  double p = 0.0;  // from the block above
  for (int k = s.n() - 1; k >= 0; --k) {
    const double h = s.heights[k];
    const double w = s.unit_weight * s.dx * h;
    const double m = k + 1 < s.n() ? std::min(s.top(k), s.top(k + 1)) - s.base(k) : 0.0;
    const double l = k > 0 ? std::min(s.top(k - 1), s.top(k)) - s.base(k) : 0.0;
    const double topple =
        k > 0 ? (p * (m - s.dx * tan_d) + 0.5 * w * (h * std::sin(a) - s.dx * std::cos(a))) / l
              : (0.5 * w * (h * std::sin(a) - s.dx * std::cos(a)) + p * (m - s.dx * tan_d) > 0.0
                     ? INFINITY
                     : -INFINITY);
    const double slide = p - w * (tan_p * std::cos(a) - std::sin(a)) / (1.0 - tan_p * tan_d);
    if (topple <= 0.0 && slide <= 0.0) {
      p = 0.0;
      continue;
    }
    out.modes[static_cast<std::size_t>(k)] = topple > slide ? Mode::topple : Mode::slide;
    p = std::max(topple, slide);
  }
  out.p0 = p;
  return out;
}

// F of Goodman & Bray: P_0(F) = 0, P_0 rising with F (bisection to round-off).
double goodman_bray_factor(const Staircase& s) {
  double lo = 1.0, hi = 5.0;
  EXPECT_LE(goodman_bray(s, lo).p0, 0.0);
  EXPECT_GT(goodman_bray(s, hi).p0, 0.0);
  for (int i = 0; i < 200 && hi - lo > 1e-14 * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    (goodman_bray(s, mid).p0 > 0.0 ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

CaseSpec staircase_case(const Staircase& s) {
  CaseSpec c;
  c.file = "staircase";
  c.block_materials = {testing::rock(10e9, 0.2, s.unit_weight)};
  const auto joint = [](const std::string& name, double phi_deg) {
    JointMaterial j = testing::springs(name, 1e10, 1e10);
    JointStrength st;
    st.friction = Softening::constant(std::tan(phi_deg * kDeg));
    j.strength = st;
    return j;
  };
  c.joint_materials = {joint("side", s.phi_side_deg), joint("tread", s.phi_base_deg)};
  std::vector<Polygon> blocks;
  for (int k = 0; k < s.n(); ++k) {
    const double x0 = k * s.dx, x1 = x0 + s.dx;
    blocks.push_back(Polygon{{{x0, s.base(k)}, {x1, s.base(k)}, {x1, s.top(k)}, {x0, s.top(k)}}});
    SupportSpec tread = testing::fixed({x0, s.base(k)}, {x1, s.base(k)});
    tread.joint_material = "tread";
    c.supports.push_back(tread);
  }
  c.blocks = testing::blocks_of(blocks);
  c.default_joint = "side";
  const double a = s.alpha_deg * kDeg;
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(-std::sin(a), -std::cos(a));  // downslope is -x
  c.stages.push_back(gravity);
  return c;
}

TEST(Toppling, StrengthReductionOfAStaircaseFollowsGoodmanAndBray) {
  const Staircase s;
  const double expected = goodman_bray_factor(s);
  const GoodmanBray at_limit = goodman_bray(s, expected * (1.0 + 1e-9));  // just past F
  const Model model = build_model(staircase_case(s));
  PlasticOptions options;
  options.factor_of_safety = FactorOfSafetyOptions{};
  options.factor_of_safety->tolerance = 1e-4;
  const PlasticResult r = run_plastic_analysis(model, options);
  ASSERT_FALSE(r.collapse.has_value()) << "the stages collapse";
  ASSERT_TRUE(r.factor_of_safety && r.factor_of_safety->collapse);
  const FactorOfSafety& f = *r.factor_of_safety;
  std::printf("F in [%.6f, %.6f], Goodman & Bray %.6f; modes from the toe:", f.lower,
              f.collapse->failed, expected);
  for (const Mode m : at_limit.modes)
    std::printf(" %s", m == Mode::stable ? "stable" : m == Mode::topple ? "topple" : "slide");
  std::printf("\n");
  EXPECT_NEAR(f.lower, expected, 1e-3 * expected);
  EXPECT_NEAR(f.collapse->failed, expected, 1e-3 * expected);
  // Each block's part in the mechanism, from its rigid motion (u0, v0, theta of the direction),
  // against Goodman & Bray's mode: a toppling block turns (its top corners' speed at least half
  // from the turn) about a point near its toe (the toe at most a fifth as fast as the top); a
  // sliding block's toe moves (at least half as fast as its top); a stable block stands (under
  // 1% of the fastest corner's speed). The mechanism found mixes a little sliding into the
  // toppling (toes at up to 15% of the top's speed), which Goodman & Bray's pure modes leave out.
  const Eigen::VectorXd& d = f.collapse->direction;
  const auto corner_speed = [&](int k, const Vec2& p) {
    const Vec2 c = model.blocks[static_cast<std::size_t>(k)].centroid;
    const double theta = d(6 * k + 2);
    return (Vec2(d(6 * k), d(6 * k + 1)) + theta * Vec2(c.y() - p.y(), p.x() - c.x())).norm();
  };
  double fastest = 0.0;
  for (int k = 0; k < s.n(); ++k)
    fastest = std::max(fastest, corner_speed(k, {k * s.dx, s.top(k)}));
  for (int k = 0; k < s.n(); ++k) {
    const double top = std::max(corner_speed(k, {k * s.dx, s.top(k)}),
                                corner_speed(k, {(k + 1) * s.dx, s.top(k)}));
    const double toe = corner_speed(k, {k * s.dx, s.base(k)});
    const double turn = std::abs(d(6 * k + 2)) * s.heights[static_cast<std::size_t>(k)];
    switch (at_limit.modes[static_cast<std::size_t>(k)]) {
      case Mode::stable:
        EXPECT_LT(top, 0.01 * fastest) << "block " << k;
        break;
      case Mode::topple:
        EXPECT_GE(turn, 0.5 * top) << "block " << k;
        EXPECT_LE(toe, 0.2 * top) << "block " << k;
        break;
      case Mode::slide:
        EXPECT_GE(toe, 0.5 * top) << "block " << k;
        break;
    }
  }
}

}  // namespace
}  // namespace bimrock
