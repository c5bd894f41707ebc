// output.vtk_every: a nonlinear run writes a VTK step every N carried increments and always the
// last. Expected: the example's increments counted by hand (start, gravity, 20 pull steps of
// 2 kN: 21 carried), and the unthinned run of the same case as the second method for the last
// step's content.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

namespace fs = std::filesystem;

std::string pull_out_case() {
  return testing::read_text(fs::path(BIMROCK_SOURCE_DIR) / "examples" / "pull_out" / "case.yaml");
}

TEST(VtkThinning, WritesEveryNthIncrementAndTheLast) {
  const testing::CommandResult all = testing::run_bimrock("run", pull_out_case(), "-o results -q");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const testing::CommandResult thin =
      testing::run_bimrock("run", pull_out_case() + "output: {vtk_every: 5}\n", "-o results -q");
  ASSERT_EQ(thin.exit_code, 0) << thin.err;
  // Steps 0 (the start), 5, 10, 15, 20 and 21 (the last carried increment).
  const std::string pvd = testing::read_text(thin.folder / "results" / "results.pvd");
  for (const char* time : {"\"0\"", "\"5\"", "\"10\"", "\"15\"", "\"20\"", "\"21\""})
    EXPECT_NE(pvd.find(std::string("timestep=") + time), std::string::npos) << time << pvd;
  EXPECT_EQ(pvd.find("timestep=\"1\""), std::string::npos) << pvd;
  EXPECT_TRUE(fs::exists(thin.folder / "results" / "vtk" / "step_0005.vtu"));
  EXPECT_FALSE(fs::exists(thin.folder / "results" / "vtk" / "step_0006.vtu"));
  // The last step is the same file as the unthinned run's last step.
  ASSERT_TRUE(fs::exists(all.folder / "results" / "vtk" / "step_0021.vtu"));
  EXPECT_EQ(testing::read_text(thin.folder / "results" / "vtk" / "step_0005.vtu"),
            testing::read_text(all.folder / "results" / "vtk" / "step_0021.vtu"));
  fs::remove_all(all.folder);
  fs::remove_all(thin.folder);
}

TEST(VtkThinning, AStepCountBelowOneIsBadInput) {
  const testing::CommandResult r =
      testing::run_bimrock("check", pull_out_case() + "output: {vtk_every: 0}\n");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find("output.vtk_every"), std::string::npos) << r.err;
  fs::remove_all(r.folder);
}

}  // namespace
}  // namespace bimrock
