// Verification: the patch test on an imported gmsh mesh. A unit square of 3 x 3 irregular
// quadrangles (tests/data/gmsh/patch_quads.msh, interior nodes moved), read through the case
// file's `mesh` section, its cells joined by the default continuum (penalty) interfaces, on
// rollers along the physical curves `bottom` and `left`, under uniform normal tractions on the
// physical curves `right` and `top` selected by `group:`. It must carry the tractions as a
// uniform stress in every block and strain like the plane-strain continuum.
//
// Sources of the expected numbers: equilibrium (the exact stress is the applied traction
// (s_x, s_y, 0) everywhere) and Hooke's law in plane strain:
//   eps_x = ((1 - nu^2) s_x - nu (1 + nu) s_y) / E,  eps_y = ((1 - nu^2) s_y - nu (1 + nu) s_x) /
//   E.
// The penalty interfaces add a compliance of order 1/p (docs/formulation.md): with the default
// p = 1e7 the error is below 1e-6, the tolerance of tests/verification/patch_test.cpp.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/model/model.hpp>

#include "support/patch_problem.hpp"

namespace bimrock {
namespace {

namespace patch = testing::patch;

TEST(GmshPatchTest, UniformTractionOnGroupsGivesUniformStressAndContinuumStrain) {
  // The rock and the tractions of support/patch_problem.hpp.
  const std::string text = R"(schema: 1
analysis: {plane: strain}
materials:
  granite: {E: 30.0e9, nu: 0.2}
mesh:
  file: patch_quads.msh
  materials: {rock: granite}
supports:
  - {group: bottom, type: roller}
  - {group: left, type: roller}
loads:
  tractions:
    - {group: right, normal: 3.0e6}
    - {group: top, normal: -2.0e6}
)";
  // The mesh file is found beside the case "file" named here.
  const Case c =
      read_case_string(text, std::string(BIMROCK_SOURCE_DIR) + "/tests/data/gmsh/patch.yaml");
  const Model model = build_model(c.spec);
  ASSERT_EQ(model.n_blocks(), 9);               // the file's 9 quadrangles
  ASSERT_EQ(model.loads.tractions.size(), 6u);  // 3 edges on each loaded side
  const ElasticSolution s = solve_elastic(model);

  const Eigen::Vector3d exact_stress = patch::exact_stress();
  double stress_error = 0.0;
  for (const BlockState& b : s.blocks)
    stress_error = std::max(stress_error, (b.stress - exact_stress).cwiseAbs().maxCoeff());
  EXPECT_LT(stress_error / std::max(std::abs(patch::kSx), std::abs(patch::kSy)), 1e-6);

  const Eigen::Vector3d exact_strain = patch::exact_strain();
  EXPECT_LT((s.mean_strain - exact_strain).norm() / exact_strain.norm(), 1e-6);
}

}  // namespace
}  // namespace bimrock
