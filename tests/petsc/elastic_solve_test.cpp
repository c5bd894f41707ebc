// The PETSc backend (src/bimrock/petsc) against CHOLMOD.
//
// Source of the expected numbers: a second method on the same K and P. solve_elastic factorizes
// K (a direct solve, exact to round-off); the backend solves it by conjugate gradients with
// algebraic multigrid. The displacements must agree to 1e-8 of the largest (relative, in the
// max norm) on the elastic examples and on a generated brick mass, and the residual the backend
// reports must be that of the u it returns. The same binary runs under `mpirun -n 2`
// (tests/CMakeLists.txt), where each process owns half of the blocks: the answers must not
// change.
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/petsc/elastic_solve.hpp>
#include <bimrock/petsc/runtime.hpp>
#include <bimrock/reference/reference_cases.hpp>

namespace bimrock {
namespace {

// PETSc once for the whole test program, as for a command.
class PetscEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { runtime_ = std::make_unique<PetscRuntime>(); }
  void TearDown() override { runtime_.reset(); }

 private:
  std::unique_ptr<PetscRuntime> runtime_;
};
::testing::Environment* const kPetsc = ::testing::AddGlobalTestEnvironment(new PetscEnvironment);

// `iterative`: whether conjugate gradients with multigrid must converge on this model (else MUMPS
// factorizes K); `tolerance`: of the displacements against CHOLMOD's, relative to the largest.
void expect_same_solution(const Model& model, const std::string& name, bool iterative,
                          double tolerance) {
  const ElasticSolution direct = solve_elastic(model);
  PetscSolveReport report;
  const ElasticSolution petsc = solve_elastic_with_petsc(model, report);
  const double scale = direct.u.cwiseAbs().maxCoeff();
  const double error = (petsc.u - direct.u).cwiseAbs().maxCoeff() / scale;
  std::printf(
      "%s: %d blocks, %s on %d process(es), %d iterations, residual %.2e, "
      "displacement error %.2e%s%s\n",
      name.c_str(), model.n_blocks(), report.method.c_str(), report.ranks, report.iterations,
      report.relative_residual, error, report.fallback.empty() ? "" : "; ",
      report.fallback.c_str());
  EXPECT_EQ(report.fallback.empty(), iterative) << name;
  EXPECT_GT(scale, 0.0);
  EXPECT_LT(error, tolerance) << name;
  // The reported residual is the returned u's, recomputed here with the whole K: equal to 10%
  // or to the round-off of K u (|K| |u| times a hundred unit round-offs), whichever is larger.
  const Eigen::VectorXd p = assemble_loads(model, model.loads);
  const SparseMatrix k = full_from_lower(assemble_stiffness_lower(model));
  const double residual = (p - k * petsc.u).norm() / p.norm();
  const double round_off = 100 * 1.1e-16 * (k.cwiseAbs() * petsc.u.cwiseAbs()).norm() / p.norm();
  EXPECT_NEAR(report.relative_residual, residual, std::max(0.1 * residual, round_off));
  EXPECT_LT(residual, 1e-6);
  // The fields are evaluated from u as the serial analysis does.
  ASSERT_EQ(petsc.blocks.size(), direct.blocks.size());
  EXPECT_LT((petsc.mean_strain - direct.mean_strain).norm(),
            10 * tolerance * direct.mean_strain.norm());
}

Model example(const char* name) {
  const std::filesystem::path file = std::filesystem::path(BIMROCK_SOURCE_DIR) / "examples" / name;
  return build_model(read_case_file(file.string()).spec);
}

// Jointed masses (joints of finite stiffness, no penalty interfaces): the iterations converge.
TEST(PetscElasticSolve, ConvergesAndEqualsCholmodOnJointedMasses) {
  for (const char* name :
       {"jointed_rock_mass/case1_vertical.yaml", "jointed_rock_mass/case2_horizontal.yaml",
        "jointed_rock_mass/case3_biaxial.yaml"})
    expect_same_solution(example(name), name, true, 1e-8);
  expect_same_solution(build_model(brick_mass_case(3000)), "brick mass", true, 1e-8);
}

// Penalty (continuum) interfaces make K too ill-conditioned for the iterations: MUMPS
// factorizes it. Two direct solves differ there by what the conditioning allows: the gmsh
// example's relative residual is 2e-7 with either factorization.
TEST(PetscElasticSolve, FactorizesWithMumpsWherePenaltyInterfacesDefeatTheIterations) {
  for (const char* name : {"gmsh_layered_ground/case.yaml", "rock_slope/case.yaml"})
    expect_same_solution(example(name), name, false, 1e-5);
}

}  // namespace
}  // namespace bimrock
