// The block displacement field Q (eq. 1) and the interface relative displacement B (eqs. 3-5),
// over random convex blocks and the interfaces of irregular assemblies. Independent numbers:
// central differences of u = Q d (exact for a linear field) give the strains and the rotation;
// a rigid motion and a uniform strain of the whole assembly, written as fields u(p), must be
// reproduced by every block and open no interface; B must equal the jump u_j - u_i of the
// blocks' own fields (read from the meaning of the unknowns) turned into the frame (n, s), with
// n the outward normal of block i's edge worked out here from its vertices.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"
#include "support/random_convex.hpp"

namespace bimrock {
namespace {

Vec6 random_block_unknowns(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vec6 d;
  d << u(rng), u(rng), 0.1 * u(rng), 0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng);
  return d;
}

// Irregular blocks with a fixed base and a roller side: interfaces of every kind.
Model supported_blocks(unsigned seed) {
  CaseSpec c;
  c.file = "kinematics";
  c.block_materials = {testing::rock(20e9, 0.25)};
  c.joint_materials = {testing::springs("joint", 5e10, 2e10)};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 6, seed));
  c.default_joint = "joint";
  c.supports.push_back(testing::fixed({0, 0}, {2, 0}));
  c.supports.push_back(testing::roller({0, 0}, {0, 1.5}));
  return build_model(c);
}

TEST(BlockQ, IsTheTranslationAtTheCentroidAndItsDerivativesAreTheStrains) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 50; ++trial) {
    const Polygon poly = testing::random_convex_polygon(rng, 3 + trial % 6);
    const Vec2 c = testing::fan_moments(poly).centroid;
    const Vec6 d = random_block_unknowns(rng);
    // At the centroid only the translation (u0, v0) remains.
    const Vec2 at_c = block_Q(c, c) * d;
    EXPECT_EQ(at_c.x(), d(0));
    EXPECT_EQ(at_c.y(), d(1));
    // The displacement gradient by central differences (exact for a linear field, so the
    // tolerance is round-off of a step of 1e-3 m on displacements of order 1).
    const Vec2 p = testing::random_inner_point(rng, poly);
    const double h = 1e-3;
    const Vec2 du_dx = (block_Q(c, p + Vec2(h, 0)) * d - block_Q(c, p - Vec2(h, 0)) * d) / (2 * h);
    const Vec2 du_dy = (block_Q(c, p + Vec2(0, h)) * d - block_Q(c, p - Vec2(0, h)) * d) / (2 * h);
    const double tol = 1e-11;
    EXPECT_NEAR(du_dx.x(), d(3), tol);                      // eps_x = du/dx
    EXPECT_NEAR(du_dy.y(), d(4), tol);                      // eps_y = dv/dy
    EXPECT_NEAR(du_dy.x() + du_dx.y(), d(5), tol);          // gamma_xy = du/dy + dv/dx
    EXPECT_NEAR(0.5 * (du_dx.y() - du_dy.x()), d(2), tol);  // theta, counter-clockwise
    // And the field is the one the unknowns mean.
    EXPECT_LT((block_Q(c, p) * d - testing::block_displacement(c, d, p)).norm(), 1e-14);
  }
}

TEST(BlockQ, EveryBlockReproducesARigidMotionAndAUniformStrainOfTheWholeAssembly) {
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (unsigned seed : {1u, 2u, 3u}) {
    const Model m = supported_blocks(seed);
    // A rigid motion about an arbitrary point o: u(p) = t + omega z x (p - o), no strain.
    const Vec2 t(u(rng), u(rng));
    const Vec2 o(u(rng), u(rng));
    const double omega = 0.05 * u(rng);
    // A uniform strain with a rotation: u(p) = t + G p.
    Eigen::Matrix2d g;
    g << 0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng);
    for (const Block& b : m.blocks) {
      Vec6 rigid;
      const Vec2 uc = t + omega * Vec2(-(b.centroid - o).y(), (b.centroid - o).x());
      rigid << uc.x(), uc.y(), omega, 0.0, 0.0, 0.0;
      const Vec6 affine = testing::affine_unknowns<Vec6>(t, g, b.centroid);
      for (const Vec2& p : b.polygon.vertices) {
        const Vec2 expected_rigid = t + omega * Vec2(-(p - o).y(), (p - o).x());
        EXPECT_LT((block_Q(b.centroid, p) * rigid - expected_rigid).norm(), 1e-14);
        EXPECT_LT((block_Q(b.centroid, p) * affine - (t + g * p)).norm(), 1e-14);
      }
    }
  }
}

TEST(InterfaceB, IsTheJumpOfTheBlockFieldsInTheFrameOfTheOutwardNormal) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int interfaces = 0;
  int supports = 0;
  for (unsigned seed : {1u, 2u, 3u}) {
    const Model m = supported_blocks(seed);
    for (const Interface& f : m.interfaces) {
      const Block& bi = m.blocks[f.block_i];
      // n points from i into j: it is the outward normal of block i's edge (and the inward one
      // of block j's).
      const Vec2 n = testing::outward_normal_of_edge_holding(bi.polygon, f.segment);
      ASSERT_LT((f.normal - n).norm(), 1e-12);
      const Vec2 s(-n.y(), n.x());
      const Vec6 di = random_block_unknowns(rng);
      const Vec6 dj = random_block_unknowns(rng);
      for (double xi : {0.0, 0.3 + 0.4 * (u(rng) + 1.0) / 2.0, 1.0}) {
        const Vec2 p = f.segment.at(xi);
        Vec2 jump = -testing::block_displacement(bi.centroid, di, p);
        Eigen::Vector2d delta;
        if (f.is_support()) {
          delta = support_B(f.normal, bi.centroid, p) * di;  // the ground does not move
          ++supports;
        } else {
          const Block& bj = m.blocks[f.block_j];
          ASSERT_LT(
              (f.normal + testing::outward_normal_of_edge_holding(bj.polygon, f.segment)).norm(),
              1e-12);
          jump += testing::block_displacement(bj.centroid, dj, p);
          Eigen::Matrix<double, 12, 1> x;
          x << di, dj;
          delta = interface_B(f.normal, bi.centroid, bj.centroid, p) * x;
          ++interfaces;
        }
        EXPECT_NEAR(delta(0), jump.dot(n), 1e-13);
        EXPECT_NEAR(delta(1), jump.dot(s), 1e-13);
      }
    }
  }
  EXPECT_GT(interfaces, 30);
  EXPECT_GT(supports, 6);
}

TEST(InterfaceB, ACommonAffineFieldOpensNoInterfaceAndMovingAwayOpens) {
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const Model m = supported_blocks(4);
  const Vec2 t(u(rng), u(rng));
  Eigen::Matrix2d g;
  g << 0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng), 0.01 * u(rng);
  for (const Interface& f : m.interfaces) {
    if (f.is_support())
      continue;
    const Vec2& ci = m.blocks[f.block_i].centroid;
    const Vec2& cj = m.blocks[f.block_j].centroid;
    const Vec2 s(-f.normal.y(), f.normal.x());
    for (const IntegrationPoint& ip : integration_points(f.segment, Integration::gauss)) {
      const Mat2x12 b = interface_B(f.normal, ci, cj, ip.point);
      // Both blocks in one field: a rigid motion with a uniform strain leaves no gap or slip.
      Eigen::Matrix<double, 12, 1> x;
      x << testing::affine_unknowns<Vec6>(t, g, ci), testing::affine_unknowns<Vec6>(t, g, cj);
      EXPECT_LT((b * x).norm(), 1e-14);
      // Block j moved by a along n (away from i) opens the joint by a: delta_n > 0 is opening.
      const double a = 1e-3;
      x.setZero();
      x.segment<2>(6) = a * f.normal;
      EXPECT_NEAR((b * x)(0), a, 1e-18);
      EXPECT_NEAR((b * x)(1), 0.0, 1e-18);
      // Block i moved along n (into j) closes it; j moved along s slips it positively.
      x.setZero();
      x.segment<2>(0) = a * f.normal;
      EXPECT_NEAR((b * x)(0), -a, 1e-18);
      x.setZero();
      x.segment<2>(6) = a * s;
      EXPECT_NEAR((b * x)(0), 0.0, 1e-18);
      EXPECT_NEAR((b * x)(1), a, 1e-18);
    }
  }
}

TEST(SupportB, BlockLiftedOffTheGroundOpensIt) {
  const Model m = supported_blocks(5);
  int supports = 0;
  for (const Interface& f : m.interfaces) {
    if (!f.is_support())
      continue;
    ++supports;
    const Vec2& ci = m.blocks[f.block_i].centroid;
    // n points out of the block into the ground: moving the block by -a n lifts it off.
    const double a = 1e-3;
    Vec6 d = Vec6::Zero();
    d.head<2>() = -a * f.normal;
    for (const Vec2& p : {f.segment.a, f.segment.b}) {
      EXPECT_NEAR((support_B(f.normal, ci, p) * d)(0), a, 1e-18);
      EXPECT_NEAR((support_B(f.normal, ci, p) * d)(1), 0.0, 1e-18);
    }
  }
  EXPECT_GT(supports, 2);
}

}  // namespace
}  // namespace bimrock
