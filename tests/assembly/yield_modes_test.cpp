// The yield modes of a yield point (eqs. 17-20): Mohr-Coulomb with a tension cut-off on joints,
// the inscribed polygon of Mohr-Coulomb or Tresca on blocks. Independent numbers: joint values
// at stress states worked by hand; gradients a = df/dsigma and flows g = dG/dsigma against
// central differences of the yield functions and plastic potentials written here (the potential
// has the dilation psi in place of phi; associated flow, psi = phi, gives g = a); the block
// polygon against the exact criterion in principal stresses (from an eigen-decomposition of the
// stress tensor): inscribed, it lies between F cos(pi/p) and F + R (1 - cos(pi/p)), F the
// exact Mohr-Coulomb function and R the circle's radius, touching the first bound at its
// vertices and the second at the middle of its sides.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>

#include <bimrock/assembly/yield_modes.hpp>

namespace bimrock {
namespace {

// A model holding just what linearize() reads: one joint material, one block material.
Model one_of_each(const JointStrength& joint, const BlockStrength& block) {
  Model m;
  JointMaterial j;
  j.normal_stiffness = 4e10;
  j.shear_stiffness = 1.5e10;
  j.strength = joint;
  m.joint_materials = {j};
  BlockMaterial b;
  b.young = 2e10;
  b.poisson = 0.3;
  b.strength = block;
  m.block_materials = {b};
  return m;
}

YieldPoint joint_point() {
  YieldPoint p;
  p.kind = YieldPoint::Kind::interface;
  p.normal = Vec2(0.6, 0.8);
  p.weight = 1.0;
  return p;
}

YieldPoint block_point() {
  YieldPoint p;
  p.kind = YieldPoint::Kind::block;
  p.block_j = kGround;
  p.weight = 1.0;
  return p;
}

// Mohr-Coulomb with tension cut-off, tension positive: f_+ = tau + sigma_n tan(phi) - c,
// f_- = -tau + sigma_n tan(phi) - c, f_t = sigma_n - sigma_t.
Eigen::Vector3d joint_f(double tan_phi, double c, double sigma_t, double sigma_n, double tau) {
  return {tau + sigma_n * tan_phi - c, -tau + sigma_n * tan_phi - c, sigma_n - sigma_t};
}

// The potentials: G_+- = +-tau + sigma_n tan(psi), G_t = sigma_n.
Eigen::Vector3d joint_potential(double tan_psi, double sigma_n, double tau) {
  return {tau + sigma_n * tan_psi, -tau + sigma_n * tan_psi, sigma_n};
}

TEST(JointYield, ValuesAtStressStatesWorkedByHand) {
  JointStrength law;
  law.cohesion = {2e5, 5e4, 2e-3};
  law.friction = {0.8, 0.5, 4e-3};
  law.tensile = {1e5, 0.0, 1e-4};
  PlasticState s;
  // Intact: c = 2e5, tan(phi) = 0.8, sigma_t = 1e5.
  EXPECT_EQ(joint_values(law, s, -1e6, 3e5), Eigen::Vector3d(-7e5, -1.3e6, -1.1e6));
  // On the slip surface: tau = c - sigma_n tan(phi) = 2e5 + 4e5.
  EXPECT_NEAR(joint_values(law, s, -5e5, 6e5)(0), 0.0, 1e-9);
  EXPECT_NEAR(joint_values(law, s, -5e5, -6e5)(1), 0.0, 1e-9);
  // Pulled open: sigma_n = sigma_t.
  EXPECT_NEAR(joint_values(law, s, 1e5, 0.0)(2), 0.0, 1e-9);
  // Halfway through the softening of c, a quarter through tan(phi), half of sigma_t:
  // c = 1.25e5, tan(phi) = 0.725, sigma_t = 5e4.
  s.slip = 1e-3;
  s.max_gap = 5e-5;
  const Eigen::Vector3d f = joint_values(law, s, -1e6, 3e5);
  EXPECT_NEAR(f(0), 3e5 - 7.25e5 - 1.25e5, 1e-6);
  EXPECT_NEAR(f(1), -3e5 - 7.25e5 - 1.25e5, 1e-6);
  EXPECT_NEAR(f(2), -1e6 - 5e4, 1e-6);
  // Past the softening distances: the residual values.
  s.slip = 1e-2;
  s.max_gap = 1.0;
  EXPECT_EQ(joint_values(law, s, -1e6, 3e5),
            Eigen::Vector3d(3e5 - 5e5 - 5e4, -3e5 - 5e5 - 5e4, -1e6));
}

TEST(JointYield, GradientsAndFlowsAreTheDerivativesOfTheYieldFunctionsAndPotentials) {
  std::mt19937 rng(41);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    JointStrength law;
    const double tan_phi = 0.2 + unit(rng);
    law.cohesion = Softening::constant(1e5 * unit(rng));
    law.friction = Softening::constant(tan_phi);
    law.tensile = Softening::constant(5e4 * unit(rng));
    law.dilation = trial % 4 == 0 ? tan_phi : 0.3 * unit(rng);
    const Model m = one_of_each(law, BlockStrength{});
    const PlasticState s;
    const double shear = 1e6 * (unit(rng) - 0.5);  // drawn first: draws in a fixed order
    const Eigen::Vector2d r(-2e6 * unit(rng) + 1e5, shear);
    const LocalYield y = linearize(m, joint_point(), s, r);
    ASSERT_EQ(y.a.rows(), 3);
    ASSERT_EQ(y.a.cols(), 2);
    EXPECT_LT((y.f - joint_f(tan_phi, law.cohesion.peak, law.tensile.peak, r(0), r(1))).norm(),
              1e-9);
    const double h = 1e3;  // [Pa]: f and G are linear in the stress, the differences exact
    for (int k = 0; k < 2; ++k) {
      Eigen::Vector2d dr = Eigen::Vector2d::Zero();
      dr(k) = h;
      const Eigen::Vector2d rp = r + dr;
      const Eigen::Vector2d rm = r - dr;
      const Eigen::Vector3d df =
          (joint_f(tan_phi, 0.0, 0.0, rp(0), rp(1)) - joint_f(tan_phi, 0.0, 0.0, rm(0), rm(1))) /
          (2 * h);
      const Eigen::Vector3d dg = (joint_potential(law.dilation, rp(0), rp(1)) -
                                  joint_potential(law.dilation, rm(0), rm(1))) /
                                 (2 * h);
      EXPECT_LT((y.a.col(k) - df).norm(), 1e-9) << "a, component " << k;
      EXPECT_LT((y.g.col(k) - dg).norm(), 1e-9) << "g, component " << k;
    }
    if (law.dilation == tan_phi) {
      EXPECT_EQ(y.g, y.a) << "associated flow";
    } else {
      EXPECT_NE(y.g, y.a);
    }
  }
}

// The exact criterion in principal stresses s1 >= s3 (tension positive):
// F = (s1 - s3)/2 - R, R = c cos(phi) - (s1 + s3)/2 sin(phi).
struct Exact {
  double f;
  double radius;
};
Exact exact_mohr_coulomb(const Eigen::Vector3d& sigma, double c, double sin_phi) {
  Eigen::Matrix2d tensor;
  tensor << sigma(0), sigma(2), sigma(2), sigma(1);
  const Eigen::Vector2d principal =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(tensor).eigenvalues();
  const double s1 = principal(1);
  const double s3 = principal(0);
  const double radius = c * std::sqrt(1.0 - sin_phi * sin_phi) - 0.5 * (s1 + s3) * sin_phi;
  return {0.5 * (s1 - s3) - radius, radius};
}

// A stress of mean s, radius rho (half the principal difference) and major principal direction
// at angle beta to x: R(beta) diag(s + rho, s - rho) R(beta)^T.
Eigen::Vector3d stress_from_principal(double s, double rho, double beta) {
  Eigen::Matrix2d rot;
  rot << std::cos(beta), -std::sin(beta), std::sin(beta), std::cos(beta);
  const Eigen::Matrix2d t = rot * Eigen::Vector2d(s + rho, s - rho).asDiagonal() * rot.transpose();
  return {t(0, 0), t(1, 1), t(0, 1)};
}

TEST(BlockYield, PolygonIsInscribedInTheExactCriterion) {
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (const auto criterion :
       {BlockStrength::Criterion::mohr_coulomb, BlockStrength::Criterion::tresca}) {
    for (int planes : {4, 7, 12, 24}) {
      BlockStrength law;
      law.criterion = criterion;
      law.cohesion = 1e6;
      const bool tresca = criterion == BlockStrength::Criterion::tresca;
      law.friction = tresca ? 0.0 : std::sin(0.6);
      law.dilation = tresca ? 0.0 : std::sin(0.2);
      law.planes = planes;
      const Model m = one_of_each(JointStrength{}, law);
      const double inscribed = std::cos(M_PI / planes);
      const auto largest = [&](const Eigen::Vector3d& sigma) {
        const LocalYield y = linearize(m, block_point(), PlasticState{}, sigma);
        EXPECT_EQ(y.f.size(), planes);
        return y.f.maxCoeff();
      };
      const double scale = law.cohesion;
      for (int trial = 0; trial < 50; ++trial) {
        const double s = -4e6 * unit(rng) + 5e5;
        const double rho = 3e6 * unit(rng);
        const Eigen::Vector3d sigma = stress_from_principal(s, rho, M_PI * unit(rng));
        const Exact e = exact_mohr_coulomb(sigma, law.cohesion, law.friction);
        const double f = largest(sigma);
        EXPECT_GE(f, e.f * inscribed - 1e-9 * scale);
        EXPECT_LE(f, e.f + e.radius * (1.0 - inscribed) + 1e-9 * scale);
      }
      // On the exact criterion, at a vertex of the polygon (2 beta = (2k + 1) pi / p): f = 0;
      // at the middle of side k (2 beta = 2 k pi / p): f = R (1 - cos(pi/p)).
      for (int k = 0; k < planes; ++k) {
        const double s = -1e6 * (k % 3);
        const double radius =
            exact_mohr_coulomb(Eigen::Vector3d(s, s, 0.0), law.cohesion, law.friction).radius;
        const Eigen::Vector3d vertex =
            stress_from_principal(s, radius, (2 * k + 1) * M_PI / (2 * planes));
        EXPECT_NEAR(largest(vertex), 0.0, 1e-9 * scale);
        const Eigen::Vector3d middle = stress_from_principal(s, radius, k * M_PI / planes);
        EXPECT_NEAR(largest(middle), radius * (1.0 - inscribed), 1e-9 * scale);
      }
    }
  }
}

// Plane k of the polygon for the potential (psi in place of phi), in polar form round the centre
// of Mohr's circle: G_k = rho cos(theta - alpha_k) + s sin(psi) cos(pi/p), rho and theta the
// polar coordinates of ((s_x - s_y)/2, tau_xy), s the mean stress, alpha_k = 2 pi k / p.
double plane_potential(int k, int planes, double sin_psi, const Eigen::Vector3d& sigma) {
  const double x = 0.5 * (sigma(0) - sigma(1));
  const double rho = std::hypot(x, sigma(2));
  const double theta = std::atan2(sigma(2), x);
  return rho * std::cos(theta - 2.0 * M_PI * k / planes) +
         0.5 * (sigma(0) + sigma(1)) * sin_psi * std::cos(M_PI / planes);
}

TEST(BlockYield, FlowsAreTheGradientsOfTheDilatantPotential) {
  std::mt19937 rng(43);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int trial = 0; trial < 10; ++trial) {
    BlockStrength law;
    law.cohesion = 1e6;
    const double phi = 0.7 * unit(rng);
    law.friction = std::sin(phi);
    law.dilation = trial % 3 == 0 ? law.friction : std::sin(phi * unit(rng));
    law.planes = 5 + trial;
    const Model m = one_of_each(JointStrength{}, law);
    Eigen::Vector3d sigma;
    sigma(2) = 1e6 * (unit(rng) - 0.5);  // draws in a fixed order: z, y, x
    sigma(1) = 1e6 * (unit(rng) - 0.7);
    sigma(0) = 1e6 * (unit(rng) - 0.7);
    const LocalYield y = linearize(m, block_point(), PlasticState{}, sigma);
    const double h = 1e2;
    for (int k = 0; k < law.planes; ++k) {
      for (int c = 0; c < 3; ++c) {
        Eigen::Vector3d ds = Eigen::Vector3d::Zero();
        ds(c) = h;
        const double dg = (plane_potential(k, law.planes, law.dilation, sigma + ds) -
                           plane_potential(k, law.planes, law.dilation, sigma - ds)) /
                          (2 * h);
        const double df = (plane_potential(k, law.planes, law.friction, sigma + ds) -
                           plane_potential(k, law.planes, law.friction, sigma - ds)) /
                          (2 * h);
        EXPECT_NEAR(y.g(k, c), dg, 1e-7) << "plane " << k << " component " << c;
        EXPECT_NEAR(y.a(k, c), df, 1e-7) << "plane " << k << " component " << c;
      }
    }
    if (law.dilation == law.friction) {
      EXPECT_EQ(y.g, y.a) << "associated flow";
    }
    // Perfectly plastic blocks: no hardening.
    EXPECT_EQ(y.h.norm(), 0.0);
  }
}

}  // namespace
}  // namespace bimrock
