// The local stiffnesses of eq. 14: a block's t A D_b (eq. 10) and an interface's
// t integral B^T D_s B ds (eq. 13), over random convex blocks and the interfaces of irregular
// assemblies. Independent numbers: the strain energy 1/2 d^T K d against the energy density of
// isotropic elasticity written with Lame's constants, times an area summed over a triangle fan;
// the spring energy against t/2 integral (k_n delta_n^2 + k_s delta_s^2) ds of the blocks' own
// jump, integrated by Simpson's rule (exact: delta is linear along the segment), and for the
// end-point (lobatto) rule the trapezoid's closed-form excess over it. The null spaces: the
// three rigid motions of a block; the displacement fields with no jump on an interface.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/local_stiffness.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"
#include "support/random_convex.hpp"

namespace bimrock {
namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;

// Strain energy density of isotropic elasticity (engineering shear strain), from Lame's
// constants: plane strain has lambda, plane stress lambda* = 2 lambda mu / (lambda + 2 mu).
double energy_density(double young, double poisson, PlaneMode plane, double ex, double ey,
                      double gxy) {
  const double mu = young / (2.0 * (1.0 + poisson));
  double lambda = young * poisson / ((1.0 + poisson) * (1.0 - 2.0 * poisson));
  if (plane == PlaneMode::stress)
    lambda = 2.0 * lambda * mu / (lambda + 2.0 * mu);
  return 0.5 * lambda * (ex + ey) * (ex + ey) + mu * (ex * ex + ey * ey + 0.5 * gxy * gxy);
}

Model spring_supported_blocks(unsigned seed, Integration rule, double thickness) {
  CaseSpec c;
  c.file = "stiffness";
  c.settings.thickness = thickness;
  c.block_materials = {testing::rock(20e9, 0.25)};
  c.joint_materials = {testing::springs("joint", 5e10, 2e10, rule)};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 6, seed));
  c.default_joint = "joint";
  JointMaterial base = testing::springs("base", 3e10, 1e10, rule);
  c.joint_materials.push_back(base);
  SupportSpec fixed = testing::fixed({0, 0}, {2, 0});
  fixed.joint_material = "base";
  c.supports.push_back(fixed);
  SupportSpec roller = testing::roller({0, 0}, {0, 1.5});
  roller.joint_material = "base";
  c.supports.push_back(roller);
  return build_model(c);
}

// [delta_n, delta_s] at a point of interface f: the jump of the blocks' own fields (the ground
// does not move) in the frame of n and s = (-n_y, n_x).
Eigen::Vector2d jump(const Model& m, const Interface& f, const Vec12& x, const Vec2& p) {
  Vec2 u = -testing::block_displacement(m.blocks[f.block_i].centroid, x.head<6>(), p);
  if (!f.is_support())
    u += testing::block_displacement(m.blocks[f.block_j].centroid, x.tail<6>(), p);
  return {u.dot(f.normal), u.dot(Vec2(-f.normal.y(), f.normal.x()))};
}

// 1/2 x^T K x of interface f (K of its 6 or 12 unknowns).
double stiffness_energy(const Model& m, const Interface& f, const Vec12& x) {
  const double t = m.settings.thickness;
  const Vec2& ci = m.blocks[f.block_i].centroid;
  if (f.is_support())
    return 0.5 * x.head<6>().dot(support_stiffness(f, ci, t) * x.head<6>());
  return 0.5 * x.dot(interface_stiffness(f, ci, m.blocks[f.block_j].centroid, t) * x);
}

Vec12 random_pair_unknowns(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1e-3, 1e-3);
  Vec12 x;
  for (int k = 0; k < 12; ++k)
    x(k) = (k % 6 < 3 ? 1.0 : 0.1) * u(rng);
  return x;
}

TEST(BlockStiffness, EnergyIsTheElasticEnergyOfTheUniformStrainAndRigidMotionsAreFree) {
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 40; ++trial) {
    const Polygon poly = testing::random_convex_polygon(rng, 3 + trial % 7);
    const testing::FanMoments fan = testing::fan_moments(poly);
    const double poisson = 0.45 * unit(rng);  // drawn first: draws in a fixed order
    const BlockMaterial rock = testing::rock(1e9 + 9e10 * unit(rng), poisson);
    const PlaneMode plane = trial % 2 == 0 ? PlaneMode::strain : PlaneMode::stress;
    const double t = 0.2 + unit(rng);
    Block b;
    b.polygon = poly;
    b.centroid = centroid(poly);
    b.area = signed_area(poly);
    const Mat6 k = block_stiffness(b, elasticity_matrix(rock, plane), t);
    Vec6 d;
    d << unit(rng), unit(rng), unit(rng), 1e-3 * (unit(rng) - 0.5), 1e-3 * (unit(rng) - 0.5),
        1e-3 * (unit(rng) - 0.5);
    const double expected =
        t * fan.area * energy_density(rock.young, rock.poisson, plane, d(3), d(4), d(5));
    EXPECT_NEAR(0.5 * d.dot(k * d), expected, 1e-12 * expected) << "trial " << trial;
    // Symmetric, positive semi-definite, and singular exactly on the rigid motions.
    EXPECT_EQ((k - k.transpose()).norm(), 0.0);
    const Eigen::SelfAdjointEigenSolver<Mat6> eig(k);
    const double top = eig.eigenvalues()(5);
    EXPECT_GT(eig.eigenvalues()(3), 1e-3 * top);
    EXPECT_GE(eig.eigenvalues()(0), -1e-14 * top);
    Vec6 rigid;
    rigid << unit(rng), unit(rng), unit(rng), 0.0, 0.0, 0.0;
    EXPECT_EQ((k * rigid).norm(), 0.0);
  }
}

TEST(InterfaceStiffness, EnergyIsTheSpringEnergyIntegratedAlongTheInterface) {
  std::mt19937 rng(22);
  int checked = 0;
  for (unsigned seed : {1u, 2u}) {
    for (Integration rule : {Integration::gauss, Integration::lobatto}) {
      const Model m = spring_supported_blocks(seed, rule, 0.7);
      for (const Interface& f : m.interfaces) {
        const Vec12 x = random_pair_unknowns(rng);
        const double l = f.segment.length();
        const auto springs = [&](const Eigen::Vector2d& d) {
          return f.normal_stiffness * d(0) * d(0) + f.shear_stiffness * d(1) * d(1);
        };
        const Eigen::Vector2d d0 = jump(m, f, x, f.segment.a);
        const Eigen::Vector2d d1 = jump(m, f, x, f.segment.b);
        const Eigen::Vector2d dm = jump(m, f, x, f.segment.midpoint());
        // Simpson's rule: exact for the quadratic k_n delta_n^2 + k_s delta_s^2.
        const double t = m.settings.thickness;
        const double exact = 0.5 * t * l / 6.0 * (springs(d0) + 4.0 * springs(dm) + springs(d1));
        const double energy = stiffness_energy(m, f, x);
        if (rule == Integration::gauss) {
          EXPECT_NEAR(energy, exact, 1e-11 * exact);
        } else {
          // The trapezoid rule over-integrates a quadratic q by L^3 q'' / 12; here q'' is
          // 2 (k_n Dn^2 + k_s Ds^2) / L^2 with D the change of delta from end a to end b: the
          // end-point springs are stiffer to a relative rotation of the two blocks.
          const double excess = t * l * springs(d1 - d0) / 12.0;
          EXPECT_NEAR(energy, exact + excess, 1e-11 * (exact + excess));
          EXPECT_GT(excess, 1e-6 * exact);
        }
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100);
}

TEST(InterfaceStiffness, IsPositiveSemiDefiniteAndSingularOnFieldsWithNoJump) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int interfaces = 0;
  int fixed = 0;
  int rollers = 0;
  for (Integration rule : {Integration::gauss, Integration::lobatto}) {
    const Model m = spring_supported_blocks(3, rule, 0.7);
    for (const Interface& f : m.interfaces) {
      const double t = m.settings.thickness;
      const Vec2& ci = m.blocks[f.block_i].centroid;
      const Vec2 n = f.normal;
      const Vec2 s(-n.y(), n.x());
      if (!f.is_support()) {
        const Vec2& cj = m.blocks[f.block_j].centroid;
        const Mat12 k = interface_stiffness(f, ci, cj, t);
        EXPECT_LT((k - k.transpose()).norm(), 1e-15 * k.norm());
        // delta is linear along the segment: two components, each fixed by its values at two
        // points. Rank 4, null space of dimension 12 - 4 = 8.
        const Eigen::SelfAdjointEigenSolver<Mat12> eig(k);
        const double top = eig.eigenvalues()(11);
        EXPECT_LT(eig.eigenvalues().head<8>().cwiseAbs().maxCoeff(), 1e-12 * top);
        EXPECT_GT(eig.eigenvalues()(8), 1e-6 * top);
        // Six of its directions: both blocks in one affine field (a rigid motion and a uniform
        // strain of the pair).
        for (int k_field = 0; k_field < 6; ++k_field) {
          Eigen::Matrix<double, 6, 1> a = Eigen::Matrix<double, 6, 1>::Zero();
          a(k_field) = 1.0;
          const Vec2 tr(a(0), a(1));
          Eigen::Matrix2d g;
          g << a(2), a(3), a(4), a(5);
          Vec12 x;
          x << testing::affine_unknowns<Vec6>(tr, g, ci), testing::affine_unknowns<Vec6>(tr, g, cj);
          EXPECT_LT((k * x).norm(), 1e-12 * top * x.norm());
        }
        ++interfaces;
        continue;
      }
      const Mat6 k = support_stiffness(f, ci, t);
      const Eigen::SelfAdjointEigenSolver<Mat6> eig(k);
      const double top = eig.eigenvalues()(5);
      EXPECT_GE(eig.eigenvalues()(0), -1e-12 * top);
      // The fields of block i that vanish on the support's line: u = e (n . (p - a)) for
      // e = n and e = s. A roller (k_s = 0) also lets the block slide along s.
      std::vector<Vec6> free;
      for (const Vec2& e : {n, s})
        free.push_back(
            testing::affine_unknowns<Vec6>(-e * n.dot(f.segment.a), e * n.transpose(), ci));
      if (f.shear_stiffness == 0.0) {
        Vec6 slide = Vec6::Zero();
        slide.head<2>() = s;
        free.push_back(slide);
        EXPECT_LT(eig.eigenvalues().head<4>().cwiseAbs().maxCoeff(), 1e-12 * top);
        EXPECT_GT(eig.eigenvalues()(4), 1e-6 * top);
        ++rollers;
      } else {
        EXPECT_LT(eig.eigenvalues().head<2>().cwiseAbs().maxCoeff(), 1e-12 * top);
        EXPECT_GT(eig.eigenvalues()(2), 1e-6 * top);
        ++fixed;
      }
      for (const Vec6& d : free)
        EXPECT_LT((k * d).norm(), 1e-12 * top * d.norm());
      // Any other motion of the block stores energy.
      Vec6 d;
      d << u(rng), u(rng), u(rng), u(rng), u(rng), u(rng);
      EXPECT_GT(d.dot(k * d), 0.0);
    }
  }
  EXPECT_GT(interfaces, 20);
  EXPECT_GT(fixed, 2);
  EXPECT_GT(rollers, 2);
}

}  // namespace
}  // namespace bimrock
