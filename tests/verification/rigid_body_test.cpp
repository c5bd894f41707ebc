// Verification: properties every block-interfaces stiffness must have, whatever the geometry.
// Sources: rigid motions store no strain energy (eq. 1 with zero strains is a rigid motion and
// every interface relative displacement (eq. 5) vanishes under it); K is symmetric (eq. 14 is a
// sum of B^T D B terms); a connected free assembly has exactly the 3 rigid motions of the plane
// as its null space.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"

namespace bimrock {
namespace {

Model free_assembly(Integration rule, unsigned seed) {
  CaseSpec c;
  c.file = "rigid";
  c.block_materials = {testing::rock(20e9, 0.25)};
  c.joint_materials = {testing::springs("joint", 5e10, 2e10, rule)};
  c.blocks = testing::blocks_of(testing::irregular_blocks(2.0, 1.5, 7, seed));
  c.default_joint = "joint";
  return build_model(c);
}

// Global unknowns of the rigid motion (u, v, omega) of the whole assembly about the origin.
Eigen::VectorXd rigid_motion(const Model& m, double u, double v, double omega) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m.n_dofs());
  for (int k = 0; k < m.n_blocks(); ++k) {
    const Vec2& c = m.blocks[k].centroid;
    x.segment<3>(6 * k) << u - omega * c.y(), v + omega * c.x(), omega;
  }
  return x;
}

class StiffnessProperties : public ::testing::TestWithParam<std::tuple<Integration, unsigned>> {};

TEST_P(StiffnessProperties, RigidMotionsStoreNoEnergy) {
  const Model m = free_assembly(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const SparseMatrix k = full_from_lower(assemble_stiffness_lower(m));
  const double scale = k.diagonal().cwiseAbs().maxCoeff();
  for (const auto& [u, v, w] : {std::tuple{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.3, -0.2, 0.7}}) {
    const Eigen::VectorXd x = rigid_motion(m, u, v, w);
    EXPECT_LT((k * x).norm(), 1e-12 * scale * x.norm());
  }
}

TEST_P(StiffnessProperties, KIsSymmetric) {
  const Model m = free_assembly(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const SparseMatrix k = full_from_lower(assemble_stiffness_lower(m));
  const SparseMatrix kt = k.transpose();
  EXPECT_LT((k - kt).norm(), 1e-14 * k.norm());
}

TEST_P(StiffnessProperties, FreeConnectedAssemblyHasThreeRigidModes) {
  const Model m = free_assembly(std::get<0>(GetParam()), std::get<1>(GetParam()));
  const Eigen::MatrixXd k = full_from_lower(assemble_stiffness_lower(m)).toDense();
  // Scale rows/columns to unit diagonal so the spectrum is not dominated by units.
  const Eigen::VectorXd s = k.diagonal().cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd ks = s.asDiagonal() * k * s.asDiagonal();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(ks);
  const Eigen::VectorXd& lambda = eig.eigenvalues();
  const double top = lambda(lambda.size() - 1);
  EXPECT_LT(std::abs(lambda(2)), 1e-10 * top);
  EXPECT_GT(lambda(3), 1e-8 * top);
}

INSTANTIATE_TEST_SUITE_P(RandomAssemblies, StiffnessProperties,
                         ::testing::Combine(::testing::Values(Integration::lobatto,
                                                              Integration::gauss),
                                            ::testing::Values(1u, 2u, 3u)));

TEST(InterfaceKinematics, BMatchesTheJumpOfTheTwoBlockDisplacements) {
  // delta = T (u_j - u_i) with u = Q d (eqs. 1, 3-5), checked component by component.
  const Vec2 n = Vec2(3.0, 4.0) / 5.0;
  const Vec2 ci(0.1, -0.4);
  const Vec2 cj(1.3, 0.9);
  const Vec2 p(0.7, 0.2);
  Vec6 di;
  Vec6 dj;
  di << 1e-3, -2e-3, 3e-4, 1e-4, -2e-4, 5e-5;
  dj << -4e-3, 1e-3, -2e-4, 3e-5, 1e-4, -7e-5;
  Eigen::Matrix<double, 12, 1> x;
  x << di, dj;
  const Vec2 ui = block_Q(ci, p) * di;
  const Vec2 uj = block_Q(cj, p) * dj;
  const Vec2 jump = uj - ui;
  const Eigen::Vector2d delta = interface_B(n, ci, cj, p) * x;
  EXPECT_NEAR(delta(0), jump.dot(n), 1e-15);
  EXPECT_NEAR(delta(1), jump.dot(Vec2(-n.y(), n.x())), 1e-15);
}

TEST(BlockKinematics, QReproducesStrainAndRotationByFiniteDifferences) {
  // The displacement gradient of u = Q d is [[eps_x, gamma/2 - theta], [gamma/2 + theta, eps_y]].
  const Vec2 c(0.3, 0.2);
  Vec6 d;
  d << 0.1, -0.2, 0.03, 0.004, -0.005, 0.006;
  const double h = 1e-3;
  const Vec2 p(1.0, -0.5);
  const Vec2 dudx = (block_Q(c, p + Vec2(h, 0)) * d - block_Q(c, p - Vec2(h, 0)) * d) / (2 * h);
  const Vec2 dudy = (block_Q(c, p + Vec2(0, h)) * d - block_Q(c, p - Vec2(0, h)) * d) / (2 * h);
  EXPECT_NEAR(dudx.x(), d(3), 1e-12);
  EXPECT_NEAR(dudy.y(), d(4), 1e-12);
  EXPECT_NEAR(dudy.x() + dudx.y(), d(5), 1e-12);
  EXPECT_NEAR(0.5 * (dudx.y() - dudy.x()), d(2), 1e-12);
}

}  // namespace
}  // namespace bimrock
