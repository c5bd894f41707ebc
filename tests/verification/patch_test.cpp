// Verification: the patch test of the continuum limit (eq. 15). A square cut into irregular
// convex blocks (some edges touching two neighbours) joined by penalty interfaces, loaded by a
// uniform biaxial traction on rollers, must carry that traction as a uniform stress in every
// block, and strain like the plane-strain continuum.
//
// Sources of the expected numbers: equilibrium (the exact stress is the applied traction
// (s_x, s_y, 0) everywhere) and Hooke's law in plane strain:
//   eps_x = ((1 - nu^2) s_x - nu (1 + nu) s_y) / E,  eps_y = ((1 - nu^2) s_y - nu (1 + nu) s_x) /
//   E.
// The penalty interfaces add a compliance of order 1/p (docs/formulation.md), so the error
// must fall like 1/p until round-off.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>

#include "support/cases.hpp"
#include "support/irregular_blocks.hpp"
#include "support/patch_problem.hpp"

namespace bimrock {
namespace {

namespace patch = testing::patch;

struct PatchError {
  double stress;  // max over blocks of |sigma - exact| / max |s|
  double strain;  // |mean strain - exact| / |exact|
  int blocks;
};

PatchError patch_error(double penalty) {
  CaseSpec c;
  c.file = "patch";
  c.settings.penalty_factor = penalty;
  c.block_materials = {testing::rock(patch::kE, patch::kNu)};
  c.joint_materials = {testing::continuum(penalty)};
  c.blocks = testing::blocks_of(testing::irregular_blocks(1.0, 1.0, 9, 7));
  c.default_joint = "continuum";
  testing::load_biaxially(c, 1.0, 1.0, patch::kSx, patch::kSy);
  const Model model = build_model(c);
  const ElasticSolution s = solve_elastic(model);
  const Eigen::Vector3d exact_stress = patch::exact_stress();
  double stress_error = 0.0;
  for (const BlockState& b : s.blocks)
    stress_error = std::max(stress_error, (b.stress - exact_stress).cwiseAbs().maxCoeff());
  const Eigen::Vector3d exact_strain = patch::exact_strain();
  return {stress_error / std::max(std::abs(patch::kSx), std::abs(patch::kSy)),
          (s.mean_strain - exact_strain).norm() / exact_strain.norm(), model.n_blocks()};
}

TEST(PatchTest, UniformTractionGivesUniformStressAndContinuumStrain) {
  const PatchError e = patch_error(kDefaultPenaltyFactor);
  EXPECT_GT(e.blocks, 15);
  EXPECT_LT(e.stress, 1e-6);
  EXPECT_LT(e.strain, 1e-6);
}

TEST(PatchTest, ErrorFallsLikeOneOverPenaltyFactor) {
  std::printf("Patch test (%d irregular blocks): relative error vs penalty factor p\n",
              patch_error(1e2).blocks);
  std::printf("%10s %14s %14s\n", "p", "block stress", "mean strain");
  double previous = 0.0;
  for (double p : {1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10}) {
    const PatchError e = patch_error(p);
    std::printf("%10.0e %14.3e %14.3e\n", p, e.stress, e.strain);
    if (p <= 1e5 && previous > 0.0) {
      // Each tenfold stiffer penalty cuts the error about tenfold (1/p), while above round-off.
      EXPECT_LT(e.strain, 0.2 * previous) << p;
      EXPECT_GT(e.strain, 0.05 * previous) << p;
    }
    previous = e.strain;
  }
}

}  // namespace
}  // namespace bimrock
