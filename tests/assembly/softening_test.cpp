// Softening and the plastic coupling of eqs. 20-23. Independent numbers: finite differences of
// the material law written here (Mohr-Coulomb with tension cut-off, c and tan(phi) linear in the
// accumulated slip kappa down to their residual values, sigma_t linear in the largest opening;
// the blocks' inscribed polygon), with the plastic state advanced by a multiplier as the law
// says (a slip multiplier adds to kappa; the opening multiplier adds to the gap, and to the
// largest gap once the joint opens past it).
//  - h_ab = -(df_a / dkappa)(dkappa / dlambda_b) at fixed stress, mode by mode;
//  - the whole coupling N of eq. 23 as assembled (weighted by the point's length or area):
//    N_ab = -w df_a / dlambda_b, the stress following the plastic strain lambda_b g_b through
//    D (diag(k_n, k_s) of the interface, or D_b of plane strain from Lame's constants).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <utility>
#include <vector>

#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/yield_modes.hpp>
#include <bimrock/assembly/yield_system.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"
#include "support/random_convex.hpp"

namespace bimrock {
namespace {

// A parameter falling linearly from peak to residual over [0, distance], then constant.
double softened(double peak, double residual, double distance, double kappa) {
  return kappa >= distance ? residual : peak + (residual - peak) * kappa / distance;
}

struct Law {
  double c0 = 2e5, c1 = 4e4, c_distance = 2e-3;
  double tan0 = 0.9, tan1 = 0.55, tan_distance = 5e-3;
  double t0 = 1e5, t1 = 1e4, t_distance = 3e-4;
  double tan_psi = 0.15;

  [[nodiscard]] JointStrength strength() const {
    JointStrength s;
    s.cohesion = {c0, c1, c_distance};
    s.friction = {tan0, tan1, tan_distance};
    s.tensile = {t0, t1, t_distance};
    s.dilation = tan_psi;
    return s;
  }
  // f_+, f_-, f_t at stress (sigma_n, tau) after slip kappa and largest opening g_max.
  [[nodiscard]] Eigen::Vector3d f(double sigma_n, double tau, double kappa, double g_max) const {
    const double tan_phi = softened(tan0, tan1, tan_distance, kappa);
    const double c = softened(c0, c1, c_distance, kappa);
    return {tau + sigma_n * tan_phi - c, -tau + sigma_n * tan_phi - c,
            sigma_n - softened(t0, t1, t_distance, g_max)};
  }
  // dG/dR of slip +, slip -, opening.
  [[nodiscard]] Eigen::Vector2d flow(int mode) const {
    return mode == 0   ? Eigen::Vector2d(tan_psi, 1.0)
           : mode == 1 ? Eigen::Vector2d(tan_psi, -1.0)
                       : Eigen::Vector2d(1.0, 0.0);
  }
};

// The joint's state after a multiplier `lambda` of mode b (lambda < 0 only for differences).
PlasticState advanced(const PlasticState& s, int b, double lambda) {
  PlasticState out = s;
  if (b < 2) {
    out.slip += lambda;
  } else {
    out.gap += lambda;
    out.max_gap = std::max(s.max_gap, out.gap);
  }
  return out;
}

// States inside and past each softening range, the joint at, below and past its largest gap.
std::vector<PlasticState> joint_states() {
  std::vector<PlasticState> states;
  for (double slip : {0.0, 7e-4, 3e-3, 1e-2}) {
    for (auto [gap, max_gap] : {std::pair{0.0, 0.0}, {1e-4, 1e-4}, {5e-5, 2e-4}, {1e-3, 1e-3}}) {
      PlasticState s;
      s.slip = slip;
      s.gap = gap;
      s.max_gap = max_gap;
      states.push_back(s);
    }
  }
  return states;
}

TEST(JointSoftening, HardeningModuliAreTheChangeOfTheYieldFunctionsWithTheMultipliers) {
  const Law law;
  Model m;
  JointMaterial j;
  j.normal_stiffness = 3e10;
  j.shear_stiffness = 1e10;
  j.strength = law.strength();
  m.joint_materials = {j};
  YieldPoint p;
  p.normal = Vec2(0.0, 1.0);
  int softening = 0;
  for (const PlasticState& s : joint_states()) {
    for (double sigma_n : {-2e6, -1e5, 3e4}) {
      const double tau = 1e5;
      const LocalYield y = linearize(m, p, s, Eigen::Vector2d(sigma_n, tau));
      for (int b = 0; b < 3; ++b) {
        // Forward differences: the law is linear in kappa on each side of a kink, and a step
        // must not cross the end of softening (residual reached: no more softening).
        const double e = 1e-9;
        const Eigen::Vector3d df =
            (law.f(sigma_n, tau, advanced(s, b, e).slip, advanced(s, b, e).max_gap) -
             law.f(sigma_n, tau, s.slip, s.max_gap)) /
            e;
        for (int a = 0; a < 3; ++a) {
          EXPECT_NEAR(y.h(a, b), -df(a), 1e-6 * (std::abs(df(a)) + 1e3))
              << "h(" << a << ", " << b << ") at slip " << s.slip << ", gap " << s.gap
              << ", max gap " << s.max_gap << ", sigma_n " << sigma_n;
        }
        softening += y.h(b, b) < 0.0 ? 1 : 0;
      }
    }
  }
  EXPECT_GT(softening, 20) << "negative h: softening";
}

// Irregular blocks joined by softening joints on a softening base, and blocks that yield.
Model softening_assembly() {
  CaseSpec c;
  c.file = "softening";
  c.block_materials = {testing::rock(20e9, 0.25, 2e4)};
  BlockStrength b;
  b.cohesion = 1e6;
  b.friction = std::sin(0.6);
  b.dilation = std::sin(0.25);
  b.planes = 8;
  c.block_materials[0].strength = b;
  JointMaterial j = testing::springs("joint", 5e10, 2e10);
  j.strength = Law{}.strength();
  c.joint_materials = {j};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 5, 3));
  c.default_joint = "joint";
  SupportSpec base = testing::fixed({0, 0}, {2, 0});
  base.joint_material = "joint";
  c.supports.push_back(base);
  return build_model(c);
}

Eigen::Matrix3d plane_strain_lame(const BlockMaterial& m) {
  const double mu = m.young / (2.0 * (1.0 + m.poisson));
  const double lambda = m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson));
  Eigen::Matrix3d d;
  d << lambda + 2 * mu, lambda, 0, lambda, lambda + 2 * mu, 0, 0, 0, mu;
  return d;
}

// The block polygon's yield functions and potentials, plane k: rho cos(theta - alpha_k) +
// s sin cos(pi/p) - (c cos(phi) cos(pi/p) for f), in the polar form of yield_modes_test.
double block_plane(int k, int planes, double sin_angle, const Eigen::Vector3d& sigma) {
  const double x = 0.5 * (sigma(0) - sigma(1));
  return std::hypot(x, sigma(2)) * std::cos(std::atan2(sigma(2), x) - 2.0 * M_PI * k / planes) +
         0.5 * (sigma(0) + sigma(1)) * sin_angle * std::cos(M_PI / planes);
}

TEST(PlasticCoupling, NIsTheChangeOfTheWeightedYieldFunctionsWithEachMultiplier) {
  const Model m = softening_assembly();
  const Law law;
  const std::vector<YieldPoint> points = make_yield_points(m);
  // Every point in a different state of those of joint_states().
  const std::vector<PlasticState> pattern = joint_states();
  std::vector<PlasticState> states(points.size());
  std::vector<int> all(points.size());
  for (std::size_t p = 0; p < points.size(); ++p) {
    all[p] = static_cast<int>(p);
    if (points[p].is_interface())
      states[p] = pattern[p % pattern.size()];
  }
  std::mt19937 rng(51);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd u(m.n_dofs());
  for (Eigen::Index k = 0; k < u.size(); ++k)
    u(k) = (k % 6 < 3 ? 1e-4 : 1e-5) * unit(rng);
  const YieldSystem sys = assemble_yield_system(m, points, states, u, all);
  const Eigen::MatrixXd n = sys.n;
  int row = 0;
  int joints = 0;
  int blocks = 0;
  for (std::size_t p = 0; p < points.size(); ++p) {
    const YieldPoint& point = points[p];
    const double w = point.weight;
    if (point.is_interface()) {
      // The stress from the blocks' own jump, less the plastic part, on the springs.
      const Interface& f = m.interfaces[point.owner];
      Vec2 jump = -testing::block_displacement(
          m.blocks[point.block_i].centroid, Vec6(u.segment<6>(6 * point.block_i)), point.position);
      if (point.block_j != kGround)
        jump += testing::block_displacement(m.blocks[point.block_j].centroid,
                                            Vec6(u.segment<6>(6 * point.block_j)), point.position);
      const Eigen::Vector2d ks(f.normal_stiffness, f.shear_stiffness);
      const Eigen::Vector2d delta(jump.dot(f.normal), jump.dot(Vec2(-f.normal.y(), f.normal.x())));
      const Eigen::Vector2d r = ks.cwiseProduct(delta - states[p].plastic.head<2>());
      for (int b = 0; b < 3; ++b) {
        // lambda_b g_b of plastic relative displacement unloads the springs by D g_b lambda_b.
        const double e = 1e-9;
        const Eigen::Vector2d r1 = r - e * ks.cwiseProduct(law.flow(b));
        const PlasticState s1 = advanced(states[p], b, e);
        const Eigen::Vector3d df = (law.f(r1(0), r1(1), s1.slip, s1.max_gap) -
                                    law.f(r(0), r(1), states[p].slip, states[p].max_gap)) /
                                   e;
        for (int a = 0; a < 3; ++a)
          EXPECT_NEAR(n(row + a, row + b), -w * df(a), 1e-6 * w * (std::abs(df(a)) + 1e8))
              << "point " << p << " N(" << a << ", " << b << ")";
      }
      row += 3;
      ++joints;
      continue;
    }
    const BlockMaterial& material = m.block_materials[point.material];
    const BlockStrength& strength = *material.strength;
    const Eigen::Matrix3d d = plane_strain_lame(material);
    const Eigen::Vector3d sigma = d * u.segment<3>(6 * point.block_i + 3);
    const int planes = strength.planes;
    for (int b = 0; b < planes; ++b) {
      // The flow of plane b: the gradient of its potential (central differences, exact).
      Eigen::Vector3d g;
      for (int c = 0; c < 3; ++c) {
        Eigen::Vector3d ds = Eigen::Vector3d::Zero();
        ds(c) = 1e2;
        g(c) = (block_plane(b, planes, strength.dilation, sigma + ds) -
                block_plane(b, planes, strength.dilation, sigma - ds)) /
               2e2;
      }
      const Eigen::Vector3d sigma1 = sigma - 1e-9 * d * g;
      for (int a = 0; a < planes; ++a) {
        const double df = (block_plane(a, planes, strength.friction, sigma1) -
                           block_plane(a, planes, strength.friction, sigma)) /
                          1e-9;
        EXPECT_NEAR(n(row + a, row + b), -w * df, 1e-5 * w * (std::abs(df) + 1e8))
            << "block point " << p << " N(" << a << ", " << b << ")";
      }
    }
    row += planes;
    ++blocks;
  }
  EXPECT_EQ(row, sys.size());
  EXPECT_GT(joints, 30);
  EXPECT_GT(blocks, 3);
}

}  // namespace
}  // namespace bimrock
