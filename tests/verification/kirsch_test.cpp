// Verification: a circular opening excavated in rock under a biaxial in-situ stress, against the
// Kirsch solution.
//
// Source of the expected numbers: G. Kirsch (1898), the elastic stress round a circular hole in
// an infinite plate; in the form of Brady & Brown, Rock Mechanics for Underground Mining, 3rd
// ed., 2004, section 7.2 (eqs. 7.1-7.4): with far-field stresses p (vertical) and K p
// (horizontal), compression positive, theta from the horizontal,
//   sigma_tt = p/2 [(1 + K)(1 + a^2/r^2) + (1 - K)(1 + 3 a^4/r^4) cos 2 theta],
// and the wall's radial displacement caused by the excavation (plane strain, shear modulus G)
//   u_r(a) = -(p a / 4G) [(1 + K) - (3 - 4 nu)(1 - K) cos 2 theta]   (positive outwards).
// The model: a quarter of a disc of radius R = 20 a (symmetry rollers on x = 0 and y = 0, the
// in-situ stress as tractions on the outer arc), triangular blocks in rings graded from the wall
// outwards joined by continuum (penalty) interfaces, the quarter disc of the opening a fan of
// triangles of its own material, excavated in one stage. Triangles, because blocks of constant
// strain joined by penalty interfaces are the constant-strain triangle of finite elements on a
// triangle mesh (its displacement continuous), and converge; on polygons of more sides (Voronoi
// cells) the interfaces ask more continuity than the blocks' linear fields can give and the
// continuum locks (docs/formulation.md, "Continuum by penalty").
// The discretization errs in three ways: blocks of constant stress (O(h), the wall's gradient is
// steep), the finite outer boundary (O(a^2/R^2): 0.25%) and the polygonal wall (O((pi/n)^2)).
// The bounds below are what the finest mesh (48 triangles on the quarter wall) reaches; the
// errors must fall as the blocks get smaller.
// Units: SI.
#include <cmath>
#include <cstdio>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/excavation.hpp>
#include <bimrock/analysis/field_results.hpp>
#include <bimrock/analysis/plastic_analysis.hpp>
#include <bimrock/model/model.hpp>

#include "support/cases.hpp"

namespace bimrock {
namespace {

constexpr double kRadius = 1.0;      // a [m]
constexpr double kExtent = 20.0;     // R [m]
constexpr double kVertical = 10e6;   // p [Pa], compression
constexpr double kRatio = 0.5;       // K
constexpr double kRockYoung = 10e9;  // [Pa]
constexpr double kRockPoisson = 0.25;
constexpr int kWallSegments = 24;  // of the quarter circle

double kirsch_hoop(double r, double theta) {
  const double q = kRadius * kRadius / (r * r);
  const double compression =
      0.5 * kVertical *
      ((1 + kRatio) * (1 + q) + (1 - kRatio) * (1 + 3 * q * q) * std::cos(2 * theta));
  return -compression;  // tension positive
}

double kirsch_wall_displacement(double theta) {
  const double g = kRockYoung / (2 * (1 + kRockPoisson));
  return -(kVertical * kRadius / (4 * g)) *
         ((1 + kRatio) - (3 - 4 * kRockPoisson) * (1 - kRatio) * std::cos(2 * theta));
}

// The quarter [0, L]^2 less nothing: rings of triangles round the quarter disc, graded
// geometrically from r = a outwards, to a square at r = L; the disc itself a fan of triangles
// (the opening, its own material). `sectors` triangles per ring and quarter.
std::vector<Polygon> quarter_triangles(int rings, int sectors) {
  std::vector<Polygon> out;
  // Ring i's nodes at angle theta_j: on the circle r_i up to r = a (L/a)^(i / rings), blended
  // into the square of half-side r_i at the outermost ring.
  const auto node = [&](int i, int j) {
    const double t = 0.5 * M_PI * j / sectors;
    const double r = kRadius * std::pow(kExtent / kRadius, static_cast<double>(i) / rings);
    return Vec2(r * std::cos(t), r * std::sin(t));
  };
  for (int j = 0; j < sectors; ++j)
    out.push_back(Polygon{{{0, 0}, node(0, j), node(0, j + 1)}});
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < sectors; ++j) {
      out.push_back(Polygon{{node(i, j), node(i + 1, j), node(i + 1, j + 1)}});
      out.push_back(Polygon{{node(i, j), node(i + 1, j + 1), node(i, j + 1)}});
    }
  return out;
}

CaseSpec quarter(int rings, int sectors) {
  CaseSpec c;
  c.file = "kirsch";
  c.settings.plane = PlaneMode::strain;
  BlockMaterial rock = testing::rock(kRockYoung, kRockPoisson);
  BlockMaterial opening = rock;
  opening.name = "opening";
  c.block_materials = {rock, opening};
  c.joint_materials = {testing::continuum(1e7)};
  c.default_joint = "continuum";
  const std::vector<Polygon> triangles = quarter_triangles(rings, sectors);
  c.blocks = testing::blocks_of(triangles);
  for (int j = 0; j < sectors; ++j)
    c.blocks[static_cast<std::size_t>(j)].material = "opening";
  c.supports = {testing::roller({0, 0}, {kExtent, 0}), testing::roller({0, 0}, {0, kExtent})};
  // The in-situ stress on each edge of the outer arc: traction sigma0 n, uniform on a straight
  // edge (n outward, shear along (-n_y, n_x)).
  StageSpec in_situ{"in situ", {}, 1, std::nullopt, {0, "stages[0]"}};
  const Eigen::Vector3d sigma0(-kRatio * kVertical, -kVertical, 0.0);
  for (int j = 0; j < sectors; ++j) {
    const Polygon& outer = triangles[triangles.size() - 2 * static_cast<std::size_t>(sectors) +
                                     2 * static_cast<std::size_t>(j)];
    const Vec2 a = outer.vertices[1], b = outer.vertices[2];
    const Vec2 n = Vec2(b.y() - a.y(), a.x() - b.x()).normalized();
    const Vec2 t(sigma0(0) * n.x() + sigma0(2) * n.y(), sigma0(2) * n.x() + sigma0(1) * n.y());
    TractionSpec edge = testing::pressure_on(a, b, t.dot(n));
    edge.shear = t.dot(Vec2(-n.y(), n.x()));
    in_situ.loads.tractions.push_back(edge);
  }
  StageSpec excavate{"excavate", {}, 1, std::nullopt, {0, "stages[1]"}};
  BlockSelector opening_blocks;
  opening_blocks.kind = BlockSelector::Kind::material;
  opening_blocks.material = "opening";
  opening_blocks.source = {0, "stages[1].excavate"};
  excavate.excavate = opening_blocks;
  c.stages = {in_situ, excavate};
  InitialStressSpec field;
  field.uniform = sigma0;
  c.initial_stress = field;
  return c;
}

struct WallErrors {
  double hoop = 0.0;          // largest |error| of a wall block's hoop stress, over p
  double displacement = 0.0;  // largest |error| of the wall's radial displacement, over the
                              // largest Kirsch displacement
  int blocks = 0;
};

// The blocks left with an edge on the wall (both ends at radius a): their hoop stress against
// Kirsch's at their centroid, and the radial displacement of their wall edge's midpoint.
WallErrors wall_errors(int rings, int sectors) {
  const Model model = build_model(quarter(rings, sectors));
  const PlasticResult r = run_plastic_analysis(model);
  EXPECT_FALSE(r.collapse || r.stopped);
  EXPECT_LT(r.initial_stress->relative_residual, 1e-12);
  const std::vector<int>& gone = model.stages[1].excavated;
  WallErrors e;
  const double largest_u = std::abs(kirsch_wall_displacement(M_PI / 2));
  for (int b = 0; b < model.n_blocks(); ++b) {
    if (std::binary_search(gone.begin(), gone.end(), b))
      continue;
    const Polygon& poly = model.blocks[b].polygon;
    for (std::size_t k = 0; k < poly.size(); ++k) {
      const Vec2& p = poly.vertices[k];
      const Vec2& q = poly.vertices[(k + 1) % poly.size()];
      if (std::abs(p.norm() - kRadius) > 1e-9 || std::abs(q.norm() - kRadius) > 1e-9)
        continue;
      ++e.blocks;
      const Vec2 c = model.blocks[b].centroid;
      const double theta = std::atan2(c.y(), c.x());
      const Eigen::Vector3d s = block_state(model, b, r.state.u).stress;
      const double hoop = s(0) * std::sin(theta) * std::sin(theta) +
                          s(1) * std::cos(theta) * std::cos(theta) -
                          2 * s(2) * std::sin(theta) * std::cos(theta);
      e.hoop = std::max(e.hoop, std::abs(hoop - kirsch_hoop(c.norm(), theta)) / kVertical);
      const Vec2 mid = 0.5 * (p + q);
      const double t = std::atan2(mid.y(), mid.x());
      const double ur = displacement_at(model, b, mid, r.state.u).dot(mid.normalized());
      e.displacement =
          std::max(e.displacement, std::abs(ur - kirsch_wall_displacement(t)) / largest_u);
    }
  }
  return e;
}

TEST(Kirsch, TheWallOfACircularOpeningFollowsKirschAndConvergesWithTheBlockSize) {
  const WallErrors coarse = wall_errors(16, 12);
  const WallErrors fine = wall_errors(32, 24);
  const WallErrors finest = wall_errors(64, 48);
  std::printf(
      "hoop stress error %.4f / %.4f / %.4f of p; wall displacement error %.4f / %.4f / "
      "%.4f\n",
      coarse.hoop, fine.hoop, finest.hoop, coarse.displacement, fine.displacement,
      finest.displacement);
  ASSERT_EQ(finest.blocks, 48);
  EXPECT_LT(fine.hoop, coarse.hoop);
  EXPECT_LT(finest.hoop, fine.hoop);
  EXPECT_LT(fine.displacement, coarse.displacement);
  EXPECT_LT(finest.displacement, fine.displacement);
  EXPECT_LT(finest.hoop, 0.15);
  EXPECT_LT(finest.displacement, 0.01);
}

}  // namespace
}  // namespace bimrock
