// PETSC_OPTIONS is the user's input too: options PETSc cannot use end the command with an input
// error naming them (exit 2) and nothing written, not an internal error.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <petscsys.h>

#include <support/run_bimrock.hpp>

namespace bimrock {
namespace {

TEST(PetscOptions, AMethodPetscCannotUseIsAnInputErrorNamingTheOptions) {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  if (ranks > 1)
    GTEST_SKIP() << "starts the command, which is not done from inside an MPI run";
  const std::string text = testing::read_text(std::filesystem::path(BIMROCK_SOURCE_DIR) /
                                              "examples/jointed_rock_mass/case3_biaxial.yaml");
  ::setenv("PETSC_OPTIONS", "-pc_type no_such_preconditioner", 1);
  const testing::CommandResult r = testing::run_bimrock("run", text, "--solver petsc -o results");
  ::unsetenv("PETSC_OPTIONS");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("PETSC_OPTIONS: -pc_type no_such_preconditioner"), std::string::npos)
      << r.err;
  EXPECT_FALSE(std::filesystem::exists(r.folder / "results"));
  std::filesystem::remove_all(r.folder);
}

}  // namespace
}  // namespace bimrock
