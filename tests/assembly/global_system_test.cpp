// The global stiffness K and load vector P of eq. 14, on irregular assemblies of two materials
// with supports. Independent numbers: 1/2 U^T K U equals the total strain energy of eqs. 10
// and 13 summed here block by block (Lame's constants, triangle-fan areas) and interface by
// interface (the blocks' own jumps, Simpson's rule or the end-point rule); P . U equals the
// work of the loads on the blocks' own displacement fields (weight over a triangle fan, each
// triangle by its centroid, exact for a linear field; tractions by Simpson's rule on the edge;
// point loads at their point). A rigid translation of everything gives the resultant of the
// loads, which must be the total weight plus the applied forces.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"
#include "support/random_convex.hpp"

namespace bimrock {
namespace {

constexpr double kThickness = 0.6;
constexpr double kWidth = 2.0;
constexpr double kHeight = 1.5;

Model loaded_assembly(unsigned seed, PlaneMode plane) {
  CaseSpec c;
  c.file = "global";
  c.settings.thickness = kThickness;
  c.settings.plane = plane;
  c.block_materials = {testing::rock(20e9, 0.25, 2.6e4), testing::rock(5e9, 0.35, 2.1e4)};
  c.block_materials[1].name = "soft";
  c.joint_materials = {testing::springs("joint", 5e10, 2e10, Integration::lobatto),
                       testing::springs("gauss", 7e10, 3e10, Integration::gauss)};
  std::vector<BlockSpec> blocks =
      testing::blocks_of(testing::irregular_blocks(kWidth, kHeight, 6, seed));
  for (std::size_t k = 0; k < blocks.size(); k += 2)
    blocks[k].material = "soft";
  c.blocks = blocks;
  // Block interfaces on one rule and supports on the other, alternating with the seed.
  const bool lobatto = seed % 2 == 1;
  c.default_joint = lobatto ? "joint" : "gauss";
  SupportSpec base = testing::fixed({0, 0}, {kWidth, 0});
  base.joint_material = lobatto ? "gauss" : "joint";
  c.supports.push_back(base);
  SupportSpec side = testing::roller({0, 0}, {0, kHeight});
  side.joint_material = base.joint_material;
  c.supports.push_back(side);
  c.loads.gravity = Vec2(0.3, -1.0);
  c.loads.points.push_back({Vec2(1.3, 0.7), Vec2(2e4, -5e4), {0, "point"}});
  c.loads.points.push_back({Vec2(0.4, 1.1), Vec2(-1e4, 3e4), {0, "point"}});
  TractionSpec top = testing::pressure_on({0, kHeight}, {kWidth, kHeight}, -3e5);
  top.shear = 1e5;
  c.loads.tractions.push_back(top);
  c.loads.tractions.push_back(testing::pressure_on({kWidth, 0}, {kWidth, kHeight}, 2e5));
  return build_model(c);
}

double lame_energy_density(const BlockMaterial& m, PlaneMode plane, const Vec6& d) {
  const double mu = m.young / (2.0 * (1.0 + m.poisson));
  double lambda = m.young * m.poisson / ((1.0 + m.poisson) * (1.0 - 2.0 * m.poisson));
  if (plane == PlaneMode::stress)
    lambda = 2.0 * lambda * mu / (lambda + 2.0 * mu);
  const double tr = d(3) + d(4);
  return 0.5 * lambda * tr * tr + mu * (d(3) * d(3) + d(4) * d(4) + 0.5 * d(5) * d(5));
}

Vec6 unknowns_of(const Eigen::VectorXd& u, int block) {
  return u.segment<6>(6 * block);
}

Vec2 field(const Model& m, const Eigen::VectorXd& u, int block, const Vec2& p) {
  return testing::block_displacement(m.blocks[block].centroid, unknowns_of(u, block), p);
}

double interface_energy(const Model& m, const Interface& f, const Eigen::VectorXd& u) {
  const auto springs = [&](const Vec2& p) {
    Vec2 jump = -field(m, u, f.block_i, p);
    if (!f.is_support())
      jump += field(m, u, f.block_j, p);
    const double dn = jump.dot(f.normal);
    const double ds = jump.dot(Vec2(-f.normal.y(), f.normal.x()));
    return f.normal_stiffness * dn * dn + f.shear_stiffness * ds * ds;
  };
  const double l = f.segment.length();
  const double ends = springs(f.segment.a) + springs(f.segment.b);
  const double integral = f.integration == Integration::gauss
                              ? l / 6.0 * (ends + 4.0 * springs(f.segment.midpoint()))
                              : l / 2.0 * ends;
  return 0.5 * kThickness * integral;
}

Eigen::VectorXd random_displacements(const Model& m, std::mt19937& rng) {
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  Eigen::VectorXd u(m.n_dofs());
  for (Eigen::Index k = 0; k < u.size(); ++k)
    u(k) = (k % 6 < 3 ? 1e-3 : 1e-4) * unit(rng);
  return u;
}

TEST(GlobalStiffness, EnergyIsTheSumOfTheBlocksAndInterfacesStrainEnergy) {
  std::mt19937 rng(31);
  for (PlaneMode plane : {PlaneMode::strain, PlaneMode::stress}) {
    for (unsigned seed : {1u, 2u, 3u}) {
      const Model m = loaded_assembly(seed, plane);
      int gauss = 0;
      for (const Interface& f : m.interfaces)
        gauss += f.integration == Integration::gauss ? 1 : 0;
      ASSERT_GT(gauss, 0);
      ASSERT_LT(gauss, m.n_interfaces());
      const Eigen::MatrixXd k = full_from_lower(assemble_stiffness_lower(m)).toDense();
      for (int trial = 0; trial < 3; ++trial) {
        const Eigen::VectorXd u = random_displacements(m, rng);
        double expected = 0.0;
        for (int b = 0; b < m.n_blocks(); ++b) {
          const Block& block = m.blocks[b];
          expected +=
              kThickness * testing::fan_moments(block.polygon).area *
              lame_energy_density(m.block_materials[block.material], plane, unknowns_of(u, b));
        }
        for (const Interface& f : m.interfaces)
          expected += interface_energy(m, f, u);
        EXPECT_NEAR(0.5 * u.dot(k * u), expected, 1e-11 * expected);
      }
    }
  }
}

TEST(GlobalLoads, PIsTheWorkOfTheLoadsOnTheBlockFields) {
  std::mt19937 rng(32);
  const Model m = loaded_assembly(4, PlaneMode::strain);
  const Eigen::VectorXd p = assemble_loads(m, m.loads);
  ASSERT_EQ(m.loads.points.size(), 2u);
  ASSERT_GT(m.loads.tractions.size(), 2u);
  for (int trial = 0; trial < 5; ++trial) {
    const Eigen::VectorXd u = random_displacements(m, rng);
    double work = 0.0;
    for (int b = 0; b < m.n_blocks(); ++b) {
      // Weight: each triangle of a fan by its centroid (exact for the linear field).
      const Block& block = m.blocks[b];
      const Vec2 body = m.block_materials[block.material].unit_weight * m.loads.gravity;
      const Vec2& o = block.polygon.vertices[0];
      for (std::size_t k = 1; k + 1 < block.polygon.size(); ++k) {
        const Vec2& v1 = block.polygon.vertices[k];
        const Vec2& v2 = block.polygon.vertices[k + 1];
        const double area = 0.5 * cross(v1 - o, v2 - o);
        work += kThickness * area * body.dot(field(m, u, b, (o + v1 + v2) / 3.0));
      }
    }
    for (const PointLoad& l : m.loads.points)
      work += l.force.dot(field(m, u, l.block, l.point));
    for (const Traction& tr : m.loads.tractions) {
      // The outward normal from the block's own edge; shear along (-n_y, n_x).
      const Vec2 n =
          testing::outward_normal_of_edge_holding(m.blocks[tr.block].polygon, tr.segment);
      const Vec2 traction = tr.normal * n + tr.shear * Vec2(-n.y(), n.x());
      const auto w = [&](const Vec2& q) { return traction.dot(field(m, u, tr.block, q)); };
      work += kThickness * tr.segment.length() / 6.0 *
              (w(tr.segment.a) + 4.0 * w(tr.segment.midpoint()) + w(tr.segment.b));
    }
    EXPECT_NEAR(p.dot(u), work, 1e-12 * std::abs(work) + 1e-9);
  }
  // The resultant: a unit translation of every block does the work of the total force.
  Vec2 resultant = Vec2::Zero();
  for (int b = 0; b < m.n_blocks(); ++b)
    resultant += p.segment<2>(6 * b);
  Vec2 expected = Vec2::Zero();
  for (const Block& b : m.blocks)
    expected += kThickness * testing::fan_moments(b.polygon).area *
                m.block_materials[b.material].unit_weight * m.loads.gravity;
  expected += Vec2(2e4, -5e4) + Vec2(-1e4, 3e4);
  expected += kThickness * kWidth * Vec2(-1e5, -3e5);  // top: pressure down, shear along -x
  expected += kThickness * kHeight * Vec2(2e5, 0.0);   // right side: pull along +x
  EXPECT_LT((resultant - expected).norm(), 1e-9 * expected.norm());
}

}  // namespace
}  // namespace bimrock
