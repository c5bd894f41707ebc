// The elastic laws of blocks and joints (materials.hpp): D_b of eq. 2 and the layer springs of
// eq. 7. Independent numbers: three-dimensional isotropic Hooke's law, written as its compliance
// eps = ((1 + nu) sigma - nu tr(sigma) I) / E (engineering shear strain gamma = tau / G). In
// plane stress sigma_z = 0; in plane strain eps_z = 0. A layer of thickness h between two
// blocks: the paper's plane-stress springs (eq. 7); in plane strain, the normal spring is the
// layer's stiffness with no strain along the joint or out of the plane.
#include <gtest/gtest.h>

#include <random>

#include <Eigen/Dense>

#include <bimrock/model/materials.hpp>

namespace bimrock {
namespace {

// The 4 x 4 compliance of [s_x, s_y, s_z, tau_xy] -> [e_x, e_y, e_z, gamma_xy].
Eigen::Matrix4d compliance(double young, double poisson) {
  Eigen::Matrix4d c = Eigen::Matrix4d::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      c(i, j) = (i == j ? 1.0 : -poisson) / young;
  c(3, 3) = 2.0 * (1.0 + poisson) / young;
  return c;
}

TEST(Materials, ElasticityMatrixIsHookesLawInPlaneStressAndPlaneStrain) {
  std::mt19937 rng(71);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    BlockMaterial m;
    m.young = 1e9 + 1e11 * unit(rng);
    m.poisson = 0.49 * unit(rng);
    Eigen::Vector3d eps;
    for (int i = 2; i >= 0; --i)  // draws in a fixed order
      eps(i) = unit(rng) - 0.5;
    const Eigen::Matrix4d c = compliance(m.young, m.poisson);
    // Plane stress: sigma_z = 0, the in-plane strains follow from the 3 x 3 part.
    const Eigen::Vector3d s_stress = elasticity_matrix(m, PlaneMode::stress) * eps;
    const Eigen::Vector4d back = c * Eigen::Vector4d(s_stress(0), s_stress(1), 0.0, s_stress(2));
    EXPECT_LT((Eigen::Vector3d(back(0), back(1), back(3)) - eps).norm(), 1e-13 * eps.norm());
    // Plane strain: the sigma_z that keeps eps_z = 0 and the in-plane stresses together give
    // back eps with eps_z = 0.
    const Eigen::Vector3d s_strain = elasticity_matrix(m, PlaneMode::strain) * eps;
    const double s_z = m.poisson * (s_strain(0) + s_strain(1));
    const Eigen::Vector4d strain = c * Eigen::Vector4d(s_strain(0), s_strain(1), s_z, s_strain(2));
    EXPECT_LT((Eigen::Vector3d(strain(0), strain(1), strain(3)) - eps).norm(), 1e-13 * eps.norm());
    EXPECT_NEAR(strain(2), 0.0, 1e-13 * eps.norm());
  }
}

TEST(Materials, LayerSpringsAreThoseOfEquationSeven) {
  const double young = 3e9;
  const double h = 0.02;
  for (double poisson : {0.0, 0.2, 0.35}) {
    // eq. 7: D_s = (1/h) diag(E / (1 - nu^2), E / (2 (1 + nu))) in plane stress.
    const SpringPair stress = layer_stiffness(young, poisson, h, PlaneMode::stress);
    EXPECT_NEAR(stress.normal, young / (1.0 - poisson * poisson) / h, 1e-6 * stress.normal);
    EXPECT_NEAR(stress.shear, young / (2.0 * (1.0 + poisson)) / h, 1e-6 * stress.shear);
    // ... which is sigma_n / eps_n with eps_s = 0 and sigma_z = 0.
    const Eigen::Matrix2d in_plane = compliance(young, poisson).topLeftCorner<2, 2>();
    EXPECT_NEAR(stress.normal, in_plane.inverse()(0, 0) / h, 1e-9 * stress.normal);
    // Plane strain: sigma_n / eps_n with eps_s = eps_z = 0, the inverse of the 3 x 3 normal
    // part of the compliance.
    const Eigen::Matrix3d normal_part = compliance(young, poisson).topLeftCorner<3, 3>();
    const double constrained = normal_part.inverse()(0, 0);
    const SpringPair strain = layer_stiffness(young, poisson, h, PlaneMode::strain);
    EXPECT_NEAR(strain.normal, constrained / h, 1e-9 * strain.normal);
    EXPECT_NEAR(strain.shear, stress.shear, 1e-9 * strain.shear);
  }
}

}  // namespace
}  // namespace bimrock
