// An interrupted run leaves nothing behind: Ctrl-C or SIGTERM remove its staging folder (exit
// 128 + the signal, as a shell's interrupted command), and a later run removes the staging
// folders of runs that were killed outright (SIGKILL), once their process is proven gone.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include "support/run_bimrock.hpp"
#include "support/two_blocks_case.hpp"

namespace bimrock {
namespace {

namespace fs = std::filesystem;

int count_hidden(const fs::path& folder) {
  int n = 0;
  for (const auto& e : fs::directory_iterator(folder))
    n += e.path().filename().string().rfind(".results.", 0) == 0 ? 1 : 0;
  return n;
}

TEST(InterruptedRun, ALaterRunRemovesTheStagingOfAKilledRunButNotOfALiveOne) {
  const std::string text =
      testing::kTwoBlocksHeader + testing::kTwoBlocksBlock0 + testing::kTwoBlocksBlock1;
  testing::CommandResult first = testing::run_bimrock("check", text);
  // A pid above Linux's largest (2^22) belongs to no process; this test's own pid is alive.
  const fs::path dead = first.folder / ".results.partial-4194399";
  const fs::path dead_old = first.folder / ".results.old-4194398";
  const fs::path alive = first.folder / (".results.partial-" + std::to_string(::getpid()));
  for (const fs::path& p : {dead, dead_old, alive}) {
    fs::create_directories(p / "vtk");
    std::ofstream(p / "summary.json") << "{}";
  }
  const std::string cmd =
      "cd '" + first.folder.string() + "' && '" + BIMROCK_BINARY + "' run case.yaml -o results -q";
  ASSERT_EQ(std::system(cmd.c_str()), 0);
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_FALSE(fs::exists(dead_old));
  EXPECT_TRUE(fs::exists(alive));
  EXPECT_TRUE(fs::exists(first.folder / "results" / "summary.json"));
  fs::remove_all(first.folder);
}

TEST(InterruptedRun, SigtermRemovesTheStagingFolderAndExits143) {
  // The pull-out with dilation 0 takes seconds: time to interrupt it while it writes.
  std::string text =
      testing::read_text(fs::path(BIMROCK_SOURCE_DIR) / "examples" / "pull_out" / "case.yaml");
  const std::string from = "friction: 0.0}";
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at))
    text.replace(at, from.size(), "friction: 30}");
  testing::CommandResult r = testing::run_bimrock("check", text);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::chdir(r.folder.c_str());
    ::execl(BIMROCK_BINARY, BIMROCK_BINARY, "run", "case.yaml", "-o", "results", "-q",
            static_cast<char*>(nullptr));
    ::_exit(127);
  }
  const fs::path staging = r.folder / (".results.partial-" + std::to_string(child));
  for (int k = 0; k < 500 && !fs::exists(staging); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ASSERT_TRUE(fs::exists(staging)) << "the run never started writing";
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ::kill(child, SIGTERM);
  int status = 0;
  ::waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 143);
  EXPECT_FALSE(fs::exists(staging));
  EXPECT_FALSE(fs::exists(r.folder / "results"));
  EXPECT_EQ(count_hidden(r.folder), 0);
  fs::remove_all(r.folder);
}

}  // namespace
}  // namespace bimrock
