// Verification: the paper's example 1 (Zhang & Lu, Table 2), a rock mass cut by two joint sets.
//
// Sources of the expected numbers:
//  - Table 2 of the paper, block-interfaces row (x 1e-4): eps1 = -1.8333, 0.18405, -1.6492;
//    eps2 = 0.36809, -1.1553, -0.7872 for (sigma1, sigma2) = (10, 0), (0, 5), (10, 5) MPa
//    compression. The paper's mass is large: its table is the n -> infinity limit of our n x n
//    masses (n blocks carry n - 1 internal joints, so the mean strain converges like 1/n).
//  - Hand derivation for the continuous direction (horizontal, across the continuous vertical
//    joints): a uniform stress sigma2 is an exact solution, each column strains by
//    (1 - nu^2)/E sigma2 and each of the n - 1 vertical joints opens by sigma2 / k_n, so
//    eps2 = sigma2 [(1 - nu^2)/E + (n - 1)/(n s k_n)] and eps1 = -nu (1 + nu)/E sigma2 (plane
//    strain).
//
// Geometry (the paper's figure is lost; examples/jointed_rock_mass/README.md explains the
// reconstruction): square blocks s = 0.2 m, vertical joints continuous, horizontal joints of
// every other column shifted by s/2; direction 1 is vertical (y), direction 2 horizontal (x).
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr double kRockE = 89e9;
constexpr double kRockNu = 0.26;
constexpr double kSize = 0.2;
constexpr double kVerticalKn = 395.9e9;
constexpr double kVerticalKs = 438.8e9;
constexpr double kHorizontalKn = 531.9e9;
constexpr double kHorizontalKs = 438.8e9;

struct LoadCase {
  double sigma1;  // vertical, tension positive [Pa]
  double sigma2;  // horizontal
  double paper_eps1;
  double paper_eps2;
};
// Table 1 and Table 2 of the paper (compression is negative here: tension positive).
constexpr LoadCase kCases[3] = {{-10e6, 0.0, -1.8333e-4, 0.36809e-4},
                                {0.0, -5e6, 0.18405e-4, -1.1553e-4},
                                {-10e6, -5e6, -1.6492e-4, -0.7872e-4}};

CaseSpec jointed_mass(int n, const LoadCase& load, Integration rule) {
  CaseSpec c;
  c.file = "example1";
  c.block_materials = {testing::rock(kRockE, kRockNu)};
  c.joint_materials = {testing::springs("vertical", kVerticalKn, kVerticalKs, rule),
                       testing::springs("horizontal", kHorizontalKn, kHorizontalKs, rule)};
  c.blocks = testing::blocks_of(brick_pattern(n, n, kSize, kSize, Stagger::columns));
  c.default_joint = "vertical";
  c.joint_rules.push_back({testing::with_orientation(0.0), "horizontal", {0, "rule"}});
  testing::load_biaxially(c, n * kSize, n * kSize, load.sigma2, load.sigma1);
  return c;
}

// Mean strain (eps1 = eps_y, eps2 = eps_x) of the n x n mass.
std::pair<double, double> mean_strains(int n, const LoadCase& load, Integration rule) {
  const Model model = build_model(jointed_mass(n, load, rule));
  const ElasticSolution s = solve_elastic(model);
  return {s.mean_strain(1), s.mean_strain(0)};
}

double continuous_direction_exact(int n, double sigma2) {
  return sigma2 * ((1.0 - kRockNu * kRockNu) / kRockE + (n - 1.0) / (n * kSize * kVerticalKn));
}

TEST(JointedRockMass, ContinuousDirectionMatchesHandDerivationForEverySize) {
  for (int n : {10, 20}) {
    const auto [eps1, eps2] = mean_strains(n, kCases[1], Integration::lobatto);
    EXPECT_NEAR(eps2, continuous_direction_exact(n, kCases[1].sigma2), 1e-6 * std::abs(eps2)) << n;
    EXPECT_NEAR(eps1, -kRockNu * (1.0 + kRockNu) / kRockE * kCases[1].sigma2, 1e-6 * std::abs(eps1))
        << n;
  }
}

TEST(JointedRockMass, HandDerivedLimitReproducesThePaperInTheContinuousDirection) {
  // Independent of the code: the paper's eps2 of case 2 from the closed form alone.
  const double limit =
      kCases[1].sigma2 * ((1.0 - kRockNu * kRockNu) / kRockE + 1.0 / (kSize * kVerticalKn));
  EXPECT_NEAR(limit, kCases[1].paper_eps2, 5e-4 * std::abs(kCases[1].paper_eps2));
}

TEST(JointedRockMass, ExtrapolatedMeanStrainsMatchTable2Within0_5Percent) {
  std::printf("Example 1, mean strain x 1e-4 (eps1 vertical, eps2 horizontal), lobatto joints\n");
  std::printf("%6s %10s %10s %10s %10s %10s %10s\n", "n", "eps1 c1", "eps1 c2", "eps1 c3",
              "eps2 c1", "eps2 c2", "eps2 c3");
  const int sizes[] = {10, 20, 40, 80};
  double eps[4][3][2];
  for (int k = 0; k < 4; ++k) {
    for (int c = 0; c < 3; ++c) {
      const auto [e1, e2] = mean_strains(sizes[k], kCases[c], Integration::lobatto);
      eps[k][c][0] = e1;
      eps[k][c][1] = e2;
    }
    std::printf("%6d %10.5f %10.5f %10.5f %10.5f %10.5f %10.5f\n", sizes[k], eps[k][0][0] * 1e4,
                eps[k][1][0] * 1e4, eps[k][2][0] * 1e4, eps[k][0][1] * 1e4, eps[k][1][1] * 1e4,
                eps[k][2][1] * 1e4);
  }
  // Richardson extrapolation of f(n) = L + a / n from n = 40 and 80: L = 2 f(80) - f(40).
  double limit[3][2];
  for (int c = 0; c < 3; ++c)
    for (int d = 0; d < 2; ++d)
      limit[c][d] = 2.0 * eps[3][c][d] - eps[2][c][d];
  std::printf("%6s %10.5f %10.5f %10.5f %10.5f %10.5f %10.5f\n", "limit", limit[0][0] * 1e4,
              limit[1][0] * 1e4, limit[2][0] * 1e4, limit[0][1] * 1e4, limit[1][1] * 1e4,
              limit[2][1] * 1e4);
  std::printf("%6s %10.5f %10.5f %10.5f %10.5f %10.5f %10.5f\n", "paper",
              kCases[0].paper_eps1 * 1e4, kCases[1].paper_eps1 * 1e4, kCases[2].paper_eps1 * 1e4,
              kCases[0].paper_eps2 * 1e4, kCases[1].paper_eps2 * 1e4, kCases[2].paper_eps2 * 1e4);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(limit[c][0], kCases[c].paper_eps1, 5e-3 * std::abs(kCases[c].paper_eps1)) << c;
    EXPECT_NEAR(limit[c][1], kCases[c].paper_eps2, 5e-3 * std::abs(kCases[c].paper_eps2)) << c;
  }
}

}  // namespace
}  // namespace bimrock
