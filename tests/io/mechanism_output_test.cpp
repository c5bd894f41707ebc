// The collapse mechanism as the results folder shows it (mechanism.csv, summary.json's
// collapse section, the mechanism velocities of the last VTU step) for a block on an incline
// (tests/support/incline_case.hpp: slope along x, downslope +x, the base block 0 fixed, the
// block 1 = [0, w] x [0, h] on it) that slides, and one that topples.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/io/results_writer.hpp>

#include "support/incline_case.hpp"
#include "support/results_folder.hpp"
#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

using Row = std::map<std::string, std::string>;

std::vector<Row> read_csv(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::vector<std::string> header;
  std::vector<Row> rows;
  for (std::string line; std::getline(in, line);) {
    std::vector<std::string> cells;
    std::stringstream s(line);
    for (std::string cell; std::getline(s, cell, ',');)
      cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    Row row;
    for (std::size_t k = 0; k < header.size() && k < cells.size(); ++k)
      row[header[k]] = cells[k];
    rows.push_back(row);
  }
  return rows;
}

double number(const Row& row, const std::string& column) {
  return std::stod(row.at(column));
}

// Runs the incline case and writes its results folder; returns the folder.
std::filesystem::path run_incline(const testing::Incline& in) {
  const Model model = build_model(testing::incline_case(in));
  const std::filesystem::path out = testing::fresh_folder("mechanism-output") / "results";
  PlasticResultsWriter writer(model, {}, out);
  const PlasticResult result = run_plastic_analysis(
      model, {},
      [&](const IncrementRecord& r, const AnalysisState& s) { writer.on_increment(r, s); });
  EXPECT_TRUE(result.collapse.has_value());
  (void)writer.finish(result);
  return out;
}

std::string last_vtu(const nlohmann::json& summary) {
  std::string last;
  for (const auto& f : summary.at("files")) {
    const std::string name = f.get<std::string>();
    if (name.rfind("vtk/", 0) == 0)
      last = name;
  }
  return last;
}

TEST(MechanismOutput, ABlockSlidingDownTheSlopeMovesOnAStandingBase) {
  // Slope 35 deg, friction 30 deg: the block slides under its own weight. It translates
  // downslope (+x): normalized, (u, v, theta) = (1, 0, 0); the base does not move. At both
  // points of its joint with the base, delta_s = s . (v_j - v_i) = -1 for either choice of
  // block i (i the base: n = (0, 1), s = (-1, 0), v_j - v_i = (1, 0); i the block: n = (0, -1),
  // s = (1, 0), v_j - v_i = (-1, 0)): slip-.
  testing::Incline in;
  in.slope_deg = 35.0;
  const std::filesystem::path out = run_incline(in);

  const std::vector<Row> rows = read_csv(out / "mechanism.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("state"), "stands");
  EXPECT_EQ(rows[1].at("state"), "moves");
  EXPECT_NEAR(number(rows[1], "u"), 1.0, 1e-6);
  EXPECT_NEAR(number(rows[1], "v"), 0.0, 1e-6);
  EXPECT_NEAR(number(rows[1], "theta_per_m"), 0.0, 1e-6);
  EXPECT_NEAR(number(rows[1], "speed"), 1.0, 1e-12);
  EXPECT_LT(number(rows[0], "speed"), 1e-3);

  const nlohmann::json summary = testing::read_json(out / "summary.json");
  const nlohmann::json& collapse = summary.at("collapse");
  EXPECT_EQ(collapse.at("mechanism_blocks").at("moves"), nlohmann::json::array({1}));
  EXPECT_EQ(collapse.at("mechanism_blocks").at("rotates"), nlohmann::json::array());
  EXPECT_EQ(collapse.at("mechanism_blocks").at("stands"), nlohmann::json::array({0}));
  ASSERT_EQ(collapse.at("mechanism_joints").size(), 2u);
  for (const auto& j : collapse.at("mechanism_joints")) {
    EXPECT_EQ(j.at("net_mode"), "slip-") << j.dump();
    EXPECT_NEAR(j.at("delta_s").get<double>(), -1.0, 1e-6) << j.dump();
  }
  ASSERT_FALSE(collapse.at("mechanism").empty());
  for (const auto& e : collapse.at("mechanism"))
    EXPECT_EQ(e.at("net_mode"), "slip-") << e.dump();
  const auto files = summary.at("files");
  EXPECT_NE(std::find(files.begin(), files.end(), "mechanism.csv"), files.end());

  // The last step's mechanism velocity: (1, 0, 0) at the block's 4 corners (points 4-7, after
  // the base's), none at the base's.
  const nlohmann::json vtu = testing::read_vtu_with_meshio(out / last_vtu(summary));
  const auto& velocity = vtu.at("point_data").at("mechanism_velocity");
  for (int p = 0; p < 4; ++p)
    EXPECT_LT(std::hypot(velocity[p][0].get<double>(), velocity[p][1].get<double>()), 1e-3);
  for (int p = 4; p < 8; ++p) {
    EXPECT_NEAR(velocity[p][0].get<double>(), 1.0, 1e-6);
    EXPECT_NEAR(velocity[p][1].get<double>(), 0.0, 1e-6);
  }
}

TEST(MechanismOutput, ATallBlockTopplesAboutItsToeAndItsHeelOpens) {
  // 1 m x 2.5 m, slope 21.85 deg (just over atan(1 / 2.5) = 21.80 deg), friction 60 deg: the
  // block turns clockwise about its toe (1, 0) and does not slide. Rotation theta about the toe
  // moves the centroid (0.5, 1.25) by (-1.25 theta, -0.5 theta) and the far top corner (0, 2.5)
  // fastest, at 2.6926 |theta|; normalized so that corner moves at 1: theta = -1 / 2.6926 =
  // -0.3714, u0 = 0.4642, v0 = 0.1857. The heel (0, 0) lifts straight off the base by
  // (0, -theta): opening.
  testing::Incline in;
  in.width = 1.0;
  in.height = 2.5;
  in.friction_deg = 60.0;
  in.slope_deg = 21.85;
  const std::filesystem::path out = run_incline(in);

  const std::vector<Row> rows = read_csv(out / "mechanism.csv");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("state"), "stands");
  EXPECT_EQ(rows[1].at("state"), "rotates");
  const double corner = std::sqrt(1.0 + 2.5 * 2.5);
  EXPECT_NEAR(number(rows[1], "theta_per_m"), -1.0 / corner, 1e-6);
  EXPECT_NEAR(number(rows[1], "u"), 1.25 / corner, 1e-6);
  EXPECT_NEAR(number(rows[1], "v"), 0.5 / corner, 1e-6);

  const nlohmann::json summary = testing::read_json(out / "summary.json");
  const nlohmann::json& collapse = summary.at("collapse");
  EXPECT_EQ(collapse.at("mechanism_blocks").at("rotates"), nlohmann::json::array({1}));
  EXPECT_EQ(collapse.at("mechanism_blocks").at("stands"), nlohmann::json::array({0}));
  bool heel = false;
  for (const auto& j : collapse.at("mechanism_joints")) {
    if (std::abs(j.at("x_m").get<double>()) < 1e-9 && std::abs(j.at("y_m").get<double>()) < 1e-9) {
      heel = true;
      EXPECT_EQ(j.at("net_mode"), "opening") << j.dump();
      EXPECT_NEAR(j.at("delta_n").get<double>(), 1.0 / std::sqrt(7.25), 1e-6) << j.dump();
    } else {
      EXPECT_NE(j.at("net_mode"), "slip+") << j.dump();  // nothing slips
      EXPECT_NE(j.at("net_mode"), "slip-") << j.dump();
    }
  }
  EXPECT_TRUE(heel) << collapse.dump(1);
}

}  // namespace
}  // namespace bimrock
