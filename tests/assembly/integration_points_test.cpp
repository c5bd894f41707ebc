// The integration rules along an interface segment (docs/formulation.md). Independent numbers:
// the integrals of the monomials xi^k along a segment of length L, L^(k+1) / (k+1) with xi the
// distance from its first end. Two-point Gauss is exact up to cubics (so B^T D B, quadratic, is
// integrated exactly), the end-point rule up to linear fields only.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <bimrock/assembly/integration_points.hpp>

namespace bimrock {
namespace {

double rule_integral(const Segment& s, Integration rule, int power) {
  double sum = 0.0;
  for (const IntegrationPoint& ip : integration_points(s, rule))
    sum += ip.weight * std::pow((ip.point - s.a).norm(), power);
  return sum;
}

TEST(IntegrationPoints, GaussIsExactToCubicsAndEndPointsToLinearFields) {
  std::mt19937 rng(61);
  std::uniform_real_distribution<double> u(-3.0, 3.0);
  for (int trial = 0; trial < 20; ++trial) {
    const Segment s{Vec2(u(rng), u(rng)), Vec2(u(rng), u(rng))};
    const double l = s.length();
    for (int k = 0; k <= 3; ++k) {
      const double exact = std::pow(l, k + 1) / (k + 1);
      EXPECT_NEAR(rule_integral(s, Integration::gauss, k), exact, 1e-13 * exact) << "xi^" << k;
      if (k <= 1) {
        EXPECT_NEAR(rule_integral(s, Integration::lobatto, k), exact, 1e-13 * exact) << "xi^" << k;
      }
    }
    // xi^2 by the trapezoid: L^3 / 2, not L^3 / 3; and Gauss is not exact for xi^4.
    EXPECT_NEAR(rule_integral(s, Integration::lobatto, 2), std::pow(l, 3) / 2.0,
                1e-13 * std::pow(l, 3));
    EXPECT_GT(std::abs(rule_integral(s, Integration::gauss, 4) - std::pow(l, 5) / 5.0),
              1e-3 * std::pow(l, 5));
    // The end-point rule's points are the segment's ends (blocks pivot about their corners).
    const auto ends = integration_points(s, Integration::lobatto);
    EXPECT_EQ(ends[0].point, s.a);
    EXPECT_EQ(ends[1].point, s.b);
    // Every point lies on the segment.
    for (const IntegrationPoint& ip : integration_points(s, Integration::gauss))
      EXPECT_LT(std::abs(cross(s.b - s.a, ip.point - s.a)), 1e-12 * l * l);
  }
}

}  // namespace
}  // namespace bimrock
