// The command line itself: --version, -q anywhere, and a command line that cannot be read is
// bad input (exit 2, as the README promises). Expected: the project's version as CMake defines
// it, and the exit codes of the README.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/run_bimrock.hpp"
#include "support/two_blocks_case.hpp"

namespace bimrock {
namespace {

const std::string kCase =
    testing::kTwoBlocksHeader + testing::kTwoBlocksBlock0 + testing::kTwoBlocksBlock1;

// Runs `bimrock <args>` in a fresh folder (no case file written).
testing::CommandResult run_command(const std::string& args) {
  testing::CommandResult r = testing::run_bimrock("check", kCase);
  const std::string cmd = "cd '" + r.folder.string() + "' && '" + BIMROCK_BINARY + "' " + args +
                          " > stdout.txt 2> stderr.txt";
  const int status = std::system(cmd.c_str());
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.err = testing::read_text(r.folder / "stderr.txt");
  r.out = testing::read_text(r.folder / "stdout.txt");
  return r;
}

TEST(CommandLine, VersionIsPrintedAndWrittenInTheSummary) {
  const testing::CommandResult v = run_command("--version");
  EXPECT_EQ(v.exit_code, 0) << v.err;
  EXPECT_EQ(v.out, std::string("bimrock ") + BIMROCK_VERSION + "\n");
  const testing::CommandResult r = testing::run_bimrock("run", kCase, "-o results");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(testing::read_text(r.folder / "results" / "summary.json")
                .find(std::string("\"bimrock_version\": \"") + BIMROCK_VERSION + "\""),
            std::string::npos);
  std::filesystem::remove_all(v.folder);
  std::filesystem::remove_all(r.folder);
}

TEST(CommandLine, QuietGoesBeforeOrAfterTheSubcommand) {
  const testing::CommandResult loud = testing::run_bimrock("run", kCase, "-o results");
  ASSERT_EQ(loud.exit_code, 0) << loud.err;
  EXPECT_FALSE(loud.out.empty());  // else the test below proves nothing
  const testing::CommandResult after = testing::run_bimrock("run", kCase, "-o results -q");
  EXPECT_EQ(after.exit_code, 0) << after.err;
  EXPECT_EQ(after.out, "");
  const testing::CommandResult before = run_command("-q run case.yaml -o results");
  EXPECT_EQ(before.exit_code, 0) << before.err;
  EXPECT_EQ(before.out, "");
  for (const auto& f : {loud.folder, after.folder, before.folder})
    std::filesystem::remove_all(f);
}

TEST(CommandLine, ACommandLineThatCannotBeReadIsBadInput) {
  for (const std::string args : {"run case.yaml --no-such-option", "run", "frobnicate",
                                 "bench --models nothing", "run case.yaml --solver nothing"}) {
    const testing::CommandResult r = run_command(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    std::filesystem::remove_all(r.folder);
  }
}

TEST(CommandLine, ProgressSaysTheModelFirstThenStageAndStepOfTheirCounts) {
  const std::string pull_out = testing::read_text(std::filesystem::path(BIMROCK_SOURCE_DIR) /
                                                  "examples" / "pull_out" / "case.yaml");
  const testing::CommandResult r = testing::run_bimrock("run", pull_out, "-o results");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // The example: 14 blocks; stage 1 of 2 (gravity, 1 increment), stage 2 of 2 (pull, 30).
  const std::size_t size = r.out.find("14 blocks");
  const std::size_t first = r.out.find("stage 1/2");
  ASSERT_NE(size, std::string::npos) << r.out;
  ASSERT_NE(first, std::string::npos) << r.out;
  EXPECT_LT(size, first);
  EXPECT_NE(r.out.find("step   1 of 1:"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("stage 2/2"), std::string::npos);
  EXPECT_NE(r.out.find("step  20 of 30:"), std::string::npos);
  EXPECT_NE(r.out.find("s left"), std::string::npos);
  std::filesystem::remove_all(r.folder);
}

TEST(CommandLine, DefaultOutputFoldersOfCasesNamedAlikeDoNotCollide) {
  // Two cases both named case.yaml, in folders a/ and b/, and one in the working folder.
  testing::CommandResult r = run_command("--version");
  for (const char* sub : {"a", "b"}) {
    std::filesystem::create_directories(r.folder / sub);
    std::ofstream(r.folder / sub / "case.yaml") << kCase;
  }
  const std::string in = "cd '" + r.folder.string() + "' && '" + BIMROCK_BINARY + "' ";
  for (const char* c : {"run a/case.yaml -q", "run b/case.yaml -q", "run case.yaml -q"})
    ASSERT_EQ(std::system((in + c).c_str()), 0) << c;
  EXPECT_TRUE(std::filesystem::exists(r.folder / "results" / "a" / "case" / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(r.folder / "results" / "b" / "case" / "summary.json"));
  EXPECT_TRUE(std::filesystem::exists(r.folder / "results" / "case" / "summary.json"));
  std::filesystem::remove_all(r.folder);
}

// A staged case with --solver petsc runs on K factorized by MUMPS (docs/parallel.md) and
// says so; a command built without PETSc refuses --solver petsc before any work, as bad input,
// naming it. (Its results against the serial ones: tests/petsc/same_results.py.)
TEST(CommandLine, ThePetscSolverRunsAStagedCaseOrIsRefusedWhereLeftOut) {
  const std::string staged = std::string(BIMROCK_SOURCE_DIR) + "/examples/pull_out/case.yaml";
  const testing::CommandResult r = run_command("run '" + staged + "' --solver petsc -o results");
  if (r.exit_code == 0) {
    EXPECT_NE(r.out.find("K factorized by MUMPS on 1 process"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("COLLAPSE"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(r.folder / "results" / "summary.json"));
  } else {
    EXPECT_EQ(r.exit_code, 2) << r.err;
    EXPECT_NE(r.err.find("built without PETSc"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(r.folder / "results"));
  }
  std::filesystem::remove_all(r.folder);
}

// Started by an MPI launcher without --solver petsc, every process would solve the whole case
// alone and write the same results: refused before any work, said once (by the first process),
// for Open MPI's launcher and for those that set PMI_SIZE (MPICH, Slurm). The launch is
// simulated by its environment.
TEST(CommandLine, AnMpiStartWithoutThePetscSolverIsRefused) {
  const std::string staged = std::string(BIMROCK_SOURCE_DIR) + "/examples/pull_out/case.yaml";
  struct Launch {
    const char* size;
    const char* rank;
    const char* rank_value;
  };
  for (const Launch& l :
       {Launch{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK", "0"},
        Launch{"PMI_SIZE", "PMI_RANK", "0"}, Launch{"PMI_SIZE", "PMI_RANK", "1"}}) {
    ::setenv(l.size, "2", 1);
    ::setenv(l.rank, l.rank_value, 1);
    for (const std::string& args :
         {"run '" + staged + "' -o results",
          std::string("bench --models elastic --elastic-sizes 100 --repetitions 1")}) {
      const testing::CommandResult r = run_command(args);
      EXPECT_EQ(r.exit_code, 2) << args;
      const bool first = std::string(l.rank_value) == "0";
      EXPECT_EQ(r.err.find("without --solver petsc") != std::string::npos, first) << r.err;
      EXPECT_FALSE(std::filesystem::exists(r.folder / "results"));
      EXPECT_EQ(r.out.find("elastic model"), std::string::npos) << r.out;
      std::filesystem::remove_all(r.folder);
    }
    ::unsetenv(l.size);
    ::unsetenv(l.rank);
  }
  // One process of a launch (mpirun -n 1) runs as without it.
  ::setenv("OMPI_COMM_WORLD_SIZE", "1", 1);
  const testing::CommandResult one = run_command("run '" + staged + "' -o results -q");
  ::unsetenv("OMPI_COMM_WORLD_SIZE");
  EXPECT_EQ(one.exit_code, 0) << one.err;
  EXPECT_TRUE(std::filesystem::exists(one.folder / "results" / "summary.json"));
  std::filesystem::remove_all(one.folder);
}

// The bench's table goes where --json says, its folder made if need be; a file that cannot be
// written is refused before any run, not found out after them.
TEST(CommandLine, ABenchTableThatCannotBeWrittenIsRefusedBeforeTheRuns) {
  const testing::CommandResult made = run_command(
      "bench --models elastic --elastic-sizes 100 --repetitions 1 --json tables/bench.json");
  EXPECT_EQ(made.exit_code, 0) << made.err;
  EXPECT_TRUE(std::filesystem::exists(made.folder / "tables" / "bench.json"));
  std::filesystem::remove_all(made.folder);
  const testing::CommandResult refused = run_command(
      "bench --models elastic --elastic-sizes 100 --repetitions 1 --json /proc/none/bench.json");
  EXPECT_EQ(refused.exit_code, 2) << refused.err;
  EXPECT_NE(refused.err.find("--json"), std::string::npos) << refused.err;
  EXPECT_EQ(refused.out.find("elastic model"), std::string::npos) << refused.out;
  std::filesystem::remove_all(refused.folder);
}

}  // namespace
}  // namespace bimrock
