// The results folder is written all or nothing (docs/results.md).
#include <fstream>

#include <gtest/gtest.h>

#include <bimrock/io/output_folder.hpp>

#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

namespace fs = std::filesystem;

TEST(StagingFolder, NothingAppearsUntilCommitAndNothingStaysWithout) {
  const fs::path root = testing::fresh_folder("bimrock-staging");
  {
    StagingFolder folder(root / "out");
    std::ofstream(folder.path() / "summary.json") << "{}";
    EXPECT_FALSE(fs::exists(root / "out"));
  }  // not committed: an error happened
  EXPECT_TRUE(fs::is_empty(root)) << "the staging folder is removed";
  {
    StagingFolder folder(root / "out");
    std::ofstream(folder.path() / "summary.json") << "new";
    folder.commit();
  }
  EXPECT_EQ(testing::read_text(root / "out" / "summary.json"), "new");
  EXPECT_EQ(std::distance(fs::directory_iterator(root), fs::directory_iterator()), 1);
  fs::remove_all(root);
}

TEST(StagingFolder, ReplacesEarlierResultsWhole) {
  const fs::path root = testing::fresh_folder("bimrock-staging");
  fs::create_directories(root / "out" / "vtk");
  std::ofstream(root / "out" / "summary.json") << "old";
  std::ofstream(root / "out" / "vtk" / "step_0009.vtu") << "old";
  StagingFolder folder(root / "out");
  std::ofstream(folder.path() / "summary.json") << "new";
  folder.commit();
  EXPECT_EQ(testing::read_text(root / "out" / "summary.json"), "new");
  EXPECT_FALSE(fs::exists(root / "out" / "vtk")) << "no stale step from the earlier run";
  fs::remove_all(root);
}

TEST(StagingFolder, RefusesToReplaceAFolderThatIsNotResults) {
  const fs::path root = testing::fresh_folder("bimrock-staging");
  fs::create_directories(root / "thesis");
  std::ofstream(root / "thesis" / "chapter1.tex") << "precious";
  EXPECT_FALSE(is_replaceable_results_folder(root / "thesis"));
  EXPECT_THROW(StagingFolder{root / "thesis"}, std::runtime_error);
  EXPECT_EQ(testing::read_text(root / "thesis" / "chapter1.tex"), "precious");
  EXPECT_TRUE(is_replaceable_results_folder(root / "new"));
  fs::remove_all(root);
}

}  // namespace
}  // namespace bimrock
