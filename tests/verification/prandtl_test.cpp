// Verification: Prandtl's strip footing on a mass of many small blocks.
//
// Source of the expected number: a smooth strip footing on a weightless half-space of Tresca
// material (undrained strength c) fails at the mean pressure q_u = (2 + pi) c = 5.1416 c
// (L. Prandtl 1920, "Ueber die Haerte plastischer Koerper", Nachrichten der Gesellschaft der
// Wissenschaften zu Goettingen, Math.-phys. Klasse, 74-85; exact: statically and kinematically
// admissible fields give the same load, W.F. Chen 1975, "Limit analysis and soil plasticity",
// chapter 5). The pressure may be uniform (a flexible footing) as here.
//
// Model: half of the problem by symmetry. The footing half-width b = B/2 = 1 m loads the top
// x in [0, b] by a uniform pressure; the soil [0, ~3.5 b] x [-~1.5 b, 0] rests on a roller on the
// symmetry line x = 0 and on the far side, and on a fixed base. Prandtl's mechanism reaches
// x = 3 b and depth sqrt(2) b, so it fits (the limit load of a perfectly plastic body does not
// depend on the elastic field outside its mechanism). The blocks are "crossed triangles"
// (tests/support/footing_mesh.hpp) of cell size h = b / n, n = 1, 2, ... (B/h = 2 n). Weightless,
// plane strain, E = 1000 c, nu = 0.3. The centre of the footing is pushed down under
// displacement control (the pressure is the stage factor times c) and the collapse pressure is
// the largest pressure carried: the load-displacement curve of a perfectly plastic body rises
// to a plateau at the limit load.
//
// What each variant converges to (and why only two of them can be asked for 5%):
//  - blocks only (Tresca blocks, penalty interfaces that never yield): the blocks with penalty
//    interfaces are constant strain triangles, which in the crossed pattern carry isochoric
//    flow without locking, so the collapse pressure falls towards Prandtl's from above as h
//    shrinks. Its limit is that of the 24-plane polygon inscribed in the Tresca circle, between
//    cos(pi/24) = 0.991 and 1 times (2 + pi) c.
//  - both (Tresca blocks and cohesive interfaces): the interfaces add slip lines along the four
//    directions of the mesh, so the mass can only be weaker than with blocks only on the same
//    mesh, and is closer to Prandtl's load.
//  - interfaces only (elastic blocks, Tresca-like joints: cohesion c, friction 0, a tensile
//    strength of 1000 c so they never open): rigid blocks that slip along straight joints
//    without opening cannot rotate relative to each other, so a mechanism is blocks translating
//    with jumps along the joints, and a crossed-triangle mesh offers four directions. In the
//    limit of small blocks that is a material with a square yield criterion
//    |s_x - s_y| / 2 <= c, |tau_xy| <= c circumscribing the Tresca circle, whose strip footing
//    load lies above (2 + pi) c (roughly 5.5 c: the fan of Prandtl's mechanism shears the mass
//    in every direction, where the square is up to sqrt(2) stronger). No refinement of this mesh
//    reaches 5%: more joint directions would be needed. With B/h = 2 the best mechanism on the
//    mesh is the wedge mechanism of 45 degree slip lines, q = 6 c exactly; the test asserts that
//    (B/h = 4 and 6 carry 5.99-6.00 c before they stop, 0.06% apart between joint stiffnesses).
//
// Known solver limit: under displacement control the increment's LCP is not symmetric, and on
// the interfaces-only meshes its symmetric part has hundreds of near-zero eigenvalues, the
// smallest slightly negative (not monotone: -2.4e6 against 1.3e11 on the LCPs of 891-1 935 rows
// of B/h = 8). Where the active-set method and the semismooth Newton method do not converge,
// Lemke's rays on such LCPs are no certificates, and the complete method serves LCPs of at most
// 1 000 rows: an increment is then cut, up to ten times, and the runs end with "could not be
// solved accurately, nor shown to have no solution" once the cuts run out, on their plateau.
// Measured (joint penalty 100 / 1e4): with 12 steps B/h = 4 ends at 5.9998 / 5.9999 c, B/h = 6
// at 6.0000 / 5.9999 c, B/h = 8 at 6.0000 / 5.9994 c, and with 24 steps B/h = 8 at 5.9999 /
// 5.9986 c. The pressures carried up to that end are checked solutions, so the test keeps the
// largest of them.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/plastic_analysis.hpp>

#include "support/cases.hpp"
#include "support/footing_mesh.hpp"

// The sanitizer build (BIMROCK_SANITIZE, about 10x slower) runs only the coarse meshes.
#if defined(__SANITIZE_ADDRESS__)
#define BIMROCK_PRANDTL_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define BIMROCK_PRANDTL_SANITIZED 1
#endif
#endif
#ifndef BIMROCK_PRANDTL_SANITIZED
#define BIMROCK_PRANDTL_SANITIZED 0
#endif

namespace bimrock {
namespace {

constexpr bool kSanitized = BIMROCK_PRANDTL_SANITIZED != 0;

constexpr double kPrandtl = 2.0 + M_PI;  // q_u / c, Prandtl 1920
constexpr double kCohesion = 10e3;       // c [Pa]
constexpr double kYoung = 1000.0 * kCohesion;
constexpr double kPoisson = 0.3;
constexpr double kHalfWidth = 1.0;  // b = B / 2 [m]
constexpr int kPlanes = 24;         // the default polygon of the Tresca criterion
/// Yielding joints: k = p E / l. Stiff enough that the joints add ~1% to the elastic
/// settlement; the collapse load does not depend on it (but see the last test).
constexpr double kJointPenalty = 100.0;

enum class Yielding { interfaces, blocks, both };

const char* to_string(Yielding y) {
  switch (y) {
    case Yielding::interfaces:
      return "interfaces only";
    case Yielding::blocks:
      return "blocks only";
    case Yielding::both:
      return "blocks and interfaces";
  }
  return "";
}

struct Footing {
  Yielding yielding = Yielding::blocks;
  int n = 1;  // cells per footing half-width: h = b / n, B / h = 2 n
  double joint_penalty = kJointPenalty;
  int increments = 12;  // of the 3 cm push
};

CaseSpec footing_case(const Footing& f) {
  const double h = kHalfWidth / f.n;
  const int nx = static_cast<int>(std::ceil(3.5 * f.n));  // width ~3.5 b
  const int ny = static_cast<int>(std::ceil(1.5 * f.n));  // depth ~1.5 b > sqrt(2) b
  const double w = nx * h;
  const double d = ny * h;
  CaseSpec c;
  c.file = "prandtl";
  BlockMaterial soil = testing::rock(kYoung, kPoisson);
  if (f.yielding != Yielding::interfaces) {
    BlockStrength tresca;
    tresca.criterion = BlockStrength::Criterion::tresca;
    tresca.cohesion = kCohesion;
    tresca.planes = kPlanes;
    soil.strength = tresca;
  }
  c.block_materials = {soil};
  JointMaterial joint = testing::continuum(kDefaultPenaltyFactor);
  if (f.yielding != Yielding::blocks) {
    JointStrength tresca_like;
    tresca_like.cohesion = Softening::constant(kCohesion);
    tresca_like.tensile = Softening::constant(1000.0 * kCohesion);
    joint.strength = tresca_like;
    joint.penalty_factor = f.joint_penalty;
    joint.integration = Integration::lobatto;  // yield at the end points (docs/formulation.md)
  }
  c.joint_materials = {joint};
  c.blocks = testing::blocks_of(testing::crossed_triangles(nx, ny, h, Vec2(0.0, -d)));
  c.default_joint = "continuum";
  c.supports.push_back(testing::roller({0, -d}, {0, 0}));  // symmetry line
  c.supports.push_back(testing::roller({w, -d}, {w, 0}));
  c.supports.push_back(testing::fixed({0, -d}, {w, -d}));
  // The pressure c on the footing, scaled by the stage factor: the factor is q / c. The centre
  // of the footing moves down by 3 cm in f.increments steps (the elastic settlement at collapse
  // is ~1.5 cm).
  StageSpec load{"footing", {}, f.increments, std::nullopt, {0, "stages[0]"}};
  load.loads.tractions.push_back(testing::pressure_on({0, 0}, {kHalfWidth, 0}, -kCohesion));
  load.control = DisplacementControlSpec{"centre", Vec2(0.0, -1.0), 0.03, {0, "control"}};
  c.stages = {load};
  c.monitors.push_back({"centre", Vec2(0.0, 0.0), {0, "centre"}});
  return c;
}

struct FootingResult {
  double q = 0.0;  // collapse pressure / c: the largest pressure carried
  int blocks = 0;
  double seconds = 0.0;
  std::string note;  // how the analysis ended

  [[nodiscard]] double ratio() const { return q / kPrandtl; }
  [[nodiscard]] double error() const { return std::abs(ratio() - 1.0); }
};

FootingResult collapse_pressure(const Footing& f) {
  const auto start = std::chrono::steady_clock::now();
  const Model model = build_model(footing_case(f));
  FootingResult out;
  out.blocks = model.n_blocks();
  auto keep_peak = [&](const IncrementRecord& r, const AnalysisState&) {
    out.q = std::max(out.q, r.stage_factor);
  };
  const PlasticResult r = run_plastic_analysis(model, {}, keep_peak);
  // See the file comment: an LCP on the plateau may be neither solved accurately nor proven
  // infeasible; the analysis then stops with the carried increments.
  out.note = r.collapse  ? "collapse reported"
             : r.stopped ? "stopped: " + r.stopped->reason
                         : "plateau";
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("  %-22s B/h = %2d  %5d blocks  q_u/c = %.4f  ratio to 2+pi = %.4f  %6.2f s  (%s)\n",
              to_string(f.yielding), 2 * f.n, out.blocks, out.q, out.ratio(), out.seconds,
              out.note.c_str());
  return out;
}

// The meshes n = b / h of a refinement study; the sanitizer build keeps the first `sanitized`.
std::vector<FootingResult> refine(Yielding y, const std::vector<int>& meshes,
                                  std::size_t sanitized) {
  std::printf("Prandtl strip footing, %s (expected (2 + pi) c = %.4f c):\n", to_string(y),
              kPrandtl);
  std::vector<FootingResult> results;
  for (std::size_t k = 0; k < meshes.size(); ++k) {
    if (kSanitized && k >= sanitized) {
      std::printf("  B/h = %d skipped in the sanitizer build\n", 2 * meshes[k]);
      continue;
    }
    results.push_back(collapse_pressure({y, meshes[k]}));
  }
  return results;
}

// The smallest strength a 24-plane inscribed polygon can give: every stress of Prandtl's field
// scaled by cos(pi/24).
const double kPolygonBound = kPrandtl * std::cos(M_PI / kPlanes);

TEST(Prandtl, BlocksOnlyConvergesFromAboveToWithinFivePercent) {
  const std::vector<FootingResult> r = refine(Yielding::blocks, {1, 2, 3}, 1);
  for (const FootingResult& x : r)
    EXPECT_GT(x.q, kPolygonBound);
  if (kSanitized)
    return;
  ASSERT_EQ(r.size(), 3u);
  // Measured: 1.123 at B/h = 2, 1.045 at B/h = 4, 1.025 at B/h = 6.
  EXPECT_LT(r[1].error(), r[0].error());
  EXPECT_LT(r[2].error(), r[1].error());
  EXPECT_LT(r[1].error(), 0.05);
  EXPECT_LT(r[2].error(), 0.03);
}

TEST(Prandtl, BlocksAndInterfacesIsWeakerThanBlocksOnlyAndWithinFivePercent) {
  const std::vector<FootingResult> both = refine(Yielding::both, {1, 2, 3}, 1);
  for (const FootingResult& x : both)
    EXPECT_GT(x.q, kPolygonBound);
  // Interfaces that slip can only add mechanisms: never stronger than blocks alone on the same
  // mesh (B/h = 2: blocks only 5.774 c).
  const FootingResult blocks_only = collapse_pressure({Yielding::blocks, 1});
  EXPECT_LE(both[0].q, blocks_only.q * (1.0 + 1e-6));
  if (kSanitized)
    return;
  ASSERT_EQ(both.size(), 3u);
  // Measured: 1.036 at B/h = 2, 1.013 at B/h = 4, 1.006 at B/h = 6.
  EXPECT_LT(both[1].error(), both[0].error());
  EXPECT_LT(both[2].error(), both[1].error());
  EXPECT_LT(both[1].error(), 0.05);
  EXPECT_LT(both[2].error(), 0.03);
}

TEST(Prandtl, InterfacesOnlyFindTheFortyFiveDegreeWedgeMechanism) {
  // See the file comment: this variant converges to a strength above Prandtl's, not to it. On
  // the coarsest mesh the best mechanism has 45 degree slip lines and q = 6 c exactly, 17% above
  // (2 + pi) c. The finer meshes, whose best mechanism is not known in closed form, are checked
  // against (2 + pi) c and against each other by the last test.
  const FootingResult r = collapse_pressure({Yielding::interfaces, 1});
  EXPECT_NEAR(r.q, 6.0, 6e-3);
}

// The upper bound theorem: every mechanism of the interfaces-only block mass is a Tresca
// mechanism (rigid blocks with slip along the joints, dissipating c per unit slip), so its
// collapse pressure cannot be below (2 + pi) c; and the limit load of a perfectly plastic body
// does not depend on its elastic stiffness. Every run stays above (2 + pi) c and reaches its
// plateau, and the two joint stiffnesses agree, on B/h = 4 and 6 with 12 steps and on B/h = 8
// with 12 and 24 (its increments are cut where they fail, as on the coarser meshes).
TEST(Prandtl, InterfacesOnlyCollapseIsAnUpperBoundWhateverTheJointStiffness) {
  if (kSanitized)
    GTEST_SKIP() << "60 s in a release build; the coarse meshes are checked above";
  const auto expect_both_stiffnesses = [](int n, int steps) {
    const FootingResult soft = collapse_pressure({Yielding::interfaces, n, 100.0, steps});
    const FootingResult stiff = collapse_pressure({Yielding::interfaces, n, 1e4, steps});
    EXPECT_GE(soft.q, kPrandtl * (1.0 - 1e-3)) << "B/h = " << 2 * n << ", " << steps << " steps";
    EXPECT_GE(stiff.q, kPrandtl * (1.0 - 1e-3)) << "B/h = " << 2 * n << ", " << steps << " steps";
    EXPECT_NEAR(soft.q, stiff.q, 1e-3 * soft.q) << "B/h = " << 2 * n << ", " << steps << " steps";
  };
  for (int n : {2, 3})
    expect_both_stiffnesses(n, 12);
  for (int steps : {12, 24})
    expect_both_stiffnesses(4, steps);
}

}  // namespace
}  // namespace bimrock
