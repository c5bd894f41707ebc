// The command line itself: --version, -q anywhere, and a command line that cannot be read is
// bad input (exit 2, as the README promises). Expected: the project's version as CMake defines
// it, and the exit codes of the README.
#include <filesystem>
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
  for (const std::string args :
       {"run case.yaml --no-such-option", "run", "frobnicate", "bench --models nothing"}) {
    const testing::CommandResult r = run_command(args);
    EXPECT_EQ(r.exit_code, 2) << args << ": " << r.err;
    EXPECT_FALSE(r.err.empty()) << args;
    std::filesystem::remove_all(r.folder);
  }
}

}  // namespace
}  // namespace bimrock
