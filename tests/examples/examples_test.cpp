// The shipped examples, run as a user runs them (the bimrock command on the case files under
// examples/), with their results read back: summary.json with nlohmann/json, the VTK files with
// meshio (an independent reader). Expected numbers come from hand derivations, reciprocity and
// superposition (example 1), and plasticity theory (example 2); each is named where it is used.
#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <string>

#include <gtest/gtest.h>
#include <yaml-cpp/yaml.h>

#include "support/results_folder.hpp"
#include "support/run_bimrock.hpp"

namespace bimrock {
namespace {

namespace fs = std::filesystem;

// Runs `bimrock run <example> -o <tmp>/results` and returns the results folder.
fs::path run_example(const std::string& relative_case) {
  const fs::path folder = testing::fresh_folder("bimrock-example");
  const std::string cmd = std::string("'") + BIMROCK_BINARY + "' --quiet run '" +
                          BIMROCK_SOURCE_DIR + "/examples/" + relative_case + "' -o '" +
                          (folder / "results").string() + "'";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
  return folder / "results";
}

double strain(const nlohmann::json& summary, const char* component) {
  return summary.at("mean_strain").at(component).get<double>();
}

// Example 1 (Zhang & Lu, Table 2): 10 x 10 blocks of 0.2 m, rock E = 89 GPa, nu = 0.26, plane
// strain; vertical joints continuous (k_n = 395.9 GPa/m), horizontal joints staggered.
constexpr double kE = 89e9, kNu = 0.26, kKnVertical = 395.9e9, kSize = 0.2;
constexpr int kN = 10;

TEST(JointedRockMassExample, HorizontalLoadMatchesTheHandDerivation) {
  // Across the continuous vertical joints a uniform stress sigma_x is exact: each column
  // strains by (1 - nu^2)/E sigma_x, each of the n - 1 joints opens by sigma_x / k_n, and the
  // blocks expand sideways by -nu (1 + nu)/E sigma_x (plane strain).
  const fs::path out = run_example("jointed_rock_mass/case2_horizontal.yaml");
  const nlohmann::json s = testing::read_json(out / "summary.json");
  const double sx = -5e6;
  const double eps_x = sx * ((1 - kNu * kNu) / kE + (kN - 1) / (kN * kSize * kKnVertical));
  const double eps_y = -kNu * (1 + kNu) / kE * sx;
  EXPECT_NEAR(strain(s, "eps_x"), eps_x, 1e-9 * std::abs(eps_x));
  EXPECT_NEAR(strain(s, "eps_y"), eps_y, 1e-9 * std::abs(eps_y));
  EXPECT_NEAR(strain(s, "gamma_xy"), 0.0, 1e-9 * std::abs(eps_x));

  // The VTK file read back by meshio: one polygon per block (5 columns of 10 and 5 staggered
  // columns of 11: 105, counted by hand), one line per interface, and in every block the
  // applied stress (the uniform field is exact).
  const nlohmann::json vtu = testing::read_vtu_with_meshio(out / "vtk" / "step_0001.vtu");
  const int blocks = 5 * 10 + 5 * 11;
  const nlohmann::json& model = s.at("model");
  EXPECT_EQ(vtu.at("cells").at("polygon").get<int>(), blocks);
  EXPECT_EQ(vtu.at("cells").at("line").get<int>(),
            model.at("interfaces").get<int>() + model.at("support_interfaces").get<int>());
  const auto& stress = vtu.at("cell_data").at("stress");
  const auto& kind = vtu.at("cell_data").at("kind");
  int checked = 0;
  for (std::size_t c = 0; c < stress.size(); ++c) {
    if (kind[c][0].get<double>() != 0.0)
      continue;
    EXPECT_NEAR(stress[c][0].get<double>(), sx, 1e-6 * std::abs(sx)) << "cell " << c;
    EXPECT_NEAR(stress[c][1].get<double>(), 0.0, 1e-6 * std::abs(sx)) << "cell " << c;
    EXPECT_NEAR(stress[c][2].get<double>(), 0.0, 1e-6 * std::abs(sx)) << "cell " << c;
    ++checked;
  }
  EXPECT_EQ(checked, blocks);
  // The displacement point data: the right face moves by eps_x times the width 2 m.
  double max_ux = 0.0;
  for (const auto& u : vtu.at("point_data").at("displacement"))
    max_ux = std::max(max_ux, std::abs(u[0].get<double>()));
  EXPECT_NEAR(max_ux, std::abs(eps_x) * kN * kSize, 1e-6 * std::abs(eps_x) * kN * kSize);
  fs::remove_all(out.parent_path());
}

TEST(JointedRockMassExample, ComplianceIsSymmetricAndLoadsSuperpose) {
  // Betti's reciprocity for the mean strain under uniform boundary tractions: the strain across
  // one direction per unit stress along the other is the same both ways (the paper's Table 2
  // shows it too: 0.18405 / 5 = 0.36809 / 10). Case 3 = case 1 + case 2 (linearity).
  const fs::path out1 = run_example("jointed_rock_mass/case1_vertical.yaml");
  const fs::path out2 = run_example("jointed_rock_mass/case2_horizontal.yaml");
  const fs::path out3 = run_example("jointed_rock_mass/case3_biaxial.yaml");
  const nlohmann::json s1 = testing::read_json(out1 / "summary.json");
  const nlohmann::json s2 = testing::read_json(out2 / "summary.json");
  const nlohmann::json s3 = testing::read_json(out3 / "summary.json");
  const double sigma1 = -10e6, sigma2 = -5e6;  // vertical, horizontal
  EXPECT_NEAR(strain(s1, "eps_x") / sigma1, strain(s2, "eps_y") / sigma2,
              1e-9 * std::abs(strain(s2, "eps_y") / sigma2));
  for (const char* c : {"eps_x", "eps_y"}) {
    EXPECT_NEAR(strain(s3, c), strain(s1, c) + strain(s2, c), 1e-9 * std::abs(strain(s3, c))) << c;
  }
  for (const fs::path& p : {out1, out2, out3})
    fs::remove_all(p.parent_path());
}

// Example 2 (Zhang & Lu): a half-brick pulled out of a jointed wall by P at A; plasticity
// theory (and the paper) give collapse at P = 2 c L t = 2 x 20 kPa x 1 m x 1 m = 40 kN.
TEST(PullOutExample, CollapseLoadPlotAndMechanismAreWritten) {
  const fs::path out = run_example("pull_out/case.yaml");
  const nlohmann::json s = testing::read_json(out / "summary.json");
  ASSERT_FALSE(s.at("collapse").is_null());
  const nlohmann::json& c = s.at("collapse");
  EXPECT_EQ(c.at("stage").get<std::string>(), "pull");
  EXPECT_NEAR(c.at("carried_point_load_N").get<double>(), 40e3, 40.0);  // 0.1 %
  EXPECT_NEAR(c.at("failed_point_load_N").get<double>(), 40e3, 40.0);
  EXPECT_LE(c.at("carried_point_load_N").get<double>(), c.at("failed_point_load_N").get<double>());
  // The mechanism: the two horizontal 1 m joints of the half-brick slide (the loaded block is
  // blocks[8] in the case file: row 2, the last of five).
  int sliding_along_y_0_5 = 0, sliding_along_y_1 = 0;
  for (const auto& m : c.at("mechanism")) {
    const std::string mode = m.at("mode").get<std::string>();
    if (mode.rfind("slip", 0) != 0 || m.at("x_m").get<double>() < 5.0 - 1e-9)
      continue;
    const double y = m.at("y_m").get<double>();
    sliding_along_y_0_5 += std::abs(y - 0.5) < 1e-9 ? 1 : 0;
    sliding_along_y_1 += std::abs(y - 1.0) < 1e-9 ? 1 : 0;
  }
  EXPECT_GE(sliding_along_y_0_5, 1);
  EXPECT_GE(sliding_along_y_1, 1);

  // history.csv: the point load grows by 2 kN a step up to the collapse (40 kN).
  std::ifstream history(out / "history.csv");
  std::string line;
  std::getline(history, line);
  EXPECT_EQ(line.rfind("stage,stage_name,increment,stage_factor,point_load_N,ux_A_m,uy_A_m", 0),
            0u);
  double last_load = 0.0;
  int pull_rows = 0;
  while (std::getline(history, line)) {
    if (line.find(",pull,") == std::string::npos)
      continue;
    std::size_t pos = 0;
    for (int k = 0; k < 4; ++k)
      pos = line.find(',', pos) + 1;
    last_load = std::stod(line.substr(pos));
    ++pull_rows;
  }
  EXPECT_EQ(pull_rows, 20);  // 20 steps of 2 kN carried; the 21st is the one that fails
  EXPECT_NEAR(last_load, 40e3, 1e-6 * 40e3);

  // The plot and the pictures are real PNG files.
  for (const char* png : {"plot_A.png", "collapse.png", "final.png"}) {
    std::ifstream in(out / png, std::ios::binary);
    char magic[8] = {};
    in.read(magic, 8);
    EXPECT_EQ(std::string(magic + 1, 3), "PNG") << png;
  }
  // One VTK step per carried increment plus the initial state, all listed in results.pvd.
  const int steps =
      static_cast<int>(std::count_if(fs::directory_iterator(out / "vtk"), fs::directory_iterator(),
                                     [](const auto&) { return true; }));
  EXPECT_EQ(steps, 1 + 1 + 20);  // start, gravity, 20 pull steps
  const nlohmann::json last = testing::read_vtu_with_meshio(out / "vtk" / "step_0021.vtu");
  const auto& state = last.at("cell_data").at("interface_state");
  EXPECT_TRUE(std::any_of(state.begin(), state.end(), [](const auto& v) {
    return v[0].template get<double>() == 1.0;
  })) << "some interface has slipped";
  fs::remove_all(out.parent_path());
}

// The bolted tunnel (examples/tunnel_excavation/bolted.yaml): grouted bolts round the crown,
// installed after half the heading's release, hold the wedge that falls from the unbolted crown;
// until they are installed the two runs are the same.
TEST(Examples, BoltsInstalledAfterHalfTheReleaseHoldTheTunnelsCrown) {
  const fs::path out = run_example("tunnel_excavation/bolted.yaml");
  const nlohmann::json s = testing::read_json(out / "summary.json");
  EXPECT_TRUE(s.at("collapse").is_null());
  EXPECT_TRUE(s.at("stopped").is_null());
  const nlohmann::json& bolts = s.at("bolts");
  EXPECT_EQ(bolts.at("bolts").get<int>(), 7);
  EXPECT_EQ(bolts.at("standing_springs").get<int>(), bolts.at("springs").get<int>());
  EXPECT_GT(bolts.at("largest_capacity_used").get<double>(), 0.0);
  EXPECT_LT(bolts.at("largest_capacity_used").get<double>(), 1.0);

  // bolts.csv: every spring installed at stage 2 ('heading relaxation'), most of them stretched;
  // the anchors beyond their pretension (the rock converges towards the opening).
  std::ifstream csv(out / "bolts.csv");
  std::string line;
  std::getline(csv, line);
  int rows = 0;
  int stretched = 0;
  while (std::getline(csv, line)) {
    std::vector<std::string> cells;
    std::size_t at = 0;
    for (std::size_t comma; (comma = line.find(',', at)) != std::string::npos; at = comma + 1)
      cells.push_back(line.substr(at, comma - at));
    cells.push_back(line.substr(at));
    ASSERT_EQ(cells.size(), 20u) << line;
    EXPECT_EQ(cells[4], "2") << line;   // installed_stage
    EXPECT_EQ(cells[11], "1") << line;  // standing
    stretched += std::stod(cells[12]) > 0.0 ? 1 : 0;
    if (cells[3] == "anchored") {
      EXPECT_GT(std::stod(cells[12]), 5.0e4) << line;
    }
    ++rows;
  }
  EXPECT_EQ(rows, bolts.at("springs").get<int>());
  EXPECT_GT(2 * stretched, rows);

  // The last VTK step read back by meshio: a line cell (kind 2) per standing spring, with the
  // forces of bolts.csv.
  fs::path last_step;
  for (const fs::directory_entry& e : fs::directory_iterator(out / "vtk"))
    last_step = std::max(last_step, e.path());
  const nlohmann::json vtu = testing::read_vtu_with_meshio(last_step);
  const nlohmann::json& model = s.at("model");
  EXPECT_EQ(vtu.at("cells").at("line").get<int>(),
            model.at("interfaces").get<int>() + model.at("support_interfaces").get<int>() + rows);
  const auto& kind = vtu.at("cell_data").at("kind");
  const auto& force = vtu.at("cell_data").at("bolt_force");
  int springs = 0;
  double largest = 0.0;
  for (std::size_t c = 0; c < kind.size(); ++c) {
    if (kind[c][0].get<double>() != 2.0)
      continue;
    ++springs;
    largest = std::max(largest, force[c][0].get<double>());
  }
  EXPECT_EQ(springs, rows);
  EXPECT_NEAR(largest / 2.45e5, bolts.at("largest_capacity_used").get<double>(), 1e-12);

  // Up to the bolts' installation, the unbolted run's history.
  const fs::path plain = run_example("tunnel_excavation/case.yaml");
  const auto history = [](const fs::path& file) {
    std::ifstream in(file);
    std::vector<std::string> lines;
    for (std::string l; std::getline(in, l);)
      lines.push_back(l.substr(0, l.rfind(',')));  // without the time the increment took
    return lines;
  };
  const std::vector<std::string> bolted = history(out / "history.csv");
  const std::vector<std::string> unbolted = history(plain / "history.csv");
  ASSERT_GE(bolted.size(), 6u);
  ASSERT_GE(unbolted.size(), 6u);
  for (std::size_t k = 0; k < 6; ++k)  // the header, in situ, the heading's 4 increments
    EXPECT_EQ(bolted[k], unbolted[k]);
  EXPECT_TRUE(fs::exists(out / "final.png"));
}

}  // namespace
}  // namespace bimrock

namespace bimrock {
namespace {

// Shoelace area of a polygon given as a YAML list of [x, y] (read with yaml-cpp directly, not
// with bimrock's reader).
double shoelace(const YAML::Node& points) {
  double twice = 0.0;
  for (std::size_t k = 0; k < points.size(); ++k) {
    const YAML::Node& a = points[k];
    const YAML::Node& b = points[(k + 1) % points.size()];
    twice += a[0].as<double>() * b[1].as<double>() - b[0].as<double>() * a[1].as<double>();
  }
  return 0.5 * twice;
}

// Example 3: blocks cut from a domain by joint sets. Expected: the area of the outline less the
// tunnel, computed here from the case file's own vertices (shoelace formula), conserved by the
// cut to round-off.
TEST(RockSlopeExample, TheCutConservesAreaAndTheCaseSolves) {
  const std::filesystem::path out = run_example("rock_slope/case.yaml");
  const nlohmann::json s = testing::read_json(out / "summary.json");
  const YAML::Node domain =
      YAML::LoadFile(std::string(BIMROCK_SOURCE_DIR) + "/examples/rock_slope/case.yaml")["domain"];
  const double outline = shoelace(domain["outline"]);
  const double tunnel = shoelace(domain["holes"][0]);
  EXPECT_NEAR(outline, 3250.0, 1e-9);  // 100 x 20 + 40 x 25 + 20 x 25 / 2, by hand
  EXPECT_NEAR(s.at("model").at("area_m2").get<double>(), outline - tunnel, 1e-12 * outline);
  EXPECT_GT(s.at("model").at("blocks").get<int>(), 300);
  // Under gravity the crest settles (a sign and order-of-magnitude check: the rock column of
  // 45 m at E = 20 GPa settles about gamma H^2 / (2 E) = 1.3 mm, more with the joints).
  double crest_uy = 0.0;
  for (const auto& m : s.at("monitors"))
    if (m.at("name") == "crest")
      crest_uy = m.at("uy_m").get<double>();
  EXPECT_LT(crest_uy, -0.5e-3);
  EXPECT_GT(crest_uy, -5e-3);
  std::filesystem::remove_all(out.parent_path());
}

// Example 4: a layered ground imported from a gmsh mesh, confined laterally (rollers), under a
// uniform surcharge p. Expected (one-dimensional compression, exact for this problem): each
// layer strains by p / M with the constrained modulus M = E (1 - nu) / ((1 + nu) (1 - 2 nu))
// of plane strain, so the surface settles by p (h_soil / M_soil + h_rock / M_rock) and the rock
// head by p h_rock / M_rock. The continuum (penalty) interfaces between the cells add a
// compliance of order 1/p = 1e-7 (docs/formulation.md): tolerance 1e-6 relative.
TEST(GmshLayeredGroundExample, SettlementMatchesOneDimensionalCompression) {
  const std::filesystem::path out = run_example("gmsh_layered_ground/case.yaml");
  const nlohmann::json s = testing::read_json(out / "summary.json");
  const auto constrained = [](double e, double nu) {
    return e * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  };
  const double p = 100e3, m_soil = constrained(50e6, 0.3), m_rock = constrained(20e9, 0.25);
  const double surface = -p * (4.0 / m_soil + 6.0 / m_rock), rock_head = -p * 6.0 / m_rock;
  std::map<std::string, double> uy;
  for (const auto& m : s.at("monitors"))
    uy[m.at("name").get<std::string>()] = m.at("uy_m").get<double>();
  EXPECT_NEAR(uy.at("surface"), surface, 1e-6 * std::abs(surface));
  EXPECT_NEAR(uy.at("rock_head"), rock_head, 1e-6 * std::abs(rock_head));
  EXPECT_NEAR(strain(s, "eps_y"), surface / 10.0, 1e-6 * std::abs(surface / 10.0));
  EXPECT_NEAR(strain(s, "eps_x"), 0.0, 1e-6 * std::abs(surface / 10.0));
  // 10 m x 10 m, the area of the outline of ground.geo.
  EXPECT_NEAR(s.at("model").at("area_m2").get<double>(), 100.0, 1e-12 * 100.0);
  std::filesystem::remove_all(out.parent_path());
}

// The slope stability example: plane failure with a tension crack, dry, with a water table that
// puts 3 m of water in the crack and falls linearly along the bedding to the toe, and under a
// seismic coefficient kh = 0.1 out of the slope. Hoek & Bray's limit equilibrium (Wyllie & Mah,
// Rock Slope Engineering, 2004, eqs. 6.3-6.7; the README's table):
// F = (c A + (W (cos(psi_p) - kh sin(psi_p)) - U - V sin(psi_p)) tan(phi))
//     / (W (sin(psi_p) + kh cos(psi_p)) + V cos(psi_p)).
double hoek_bray(double water_depth, double kh) {
  const double deg = M_PI / 180.0, h = 20.0, z = 6.0, pp = 30 * deg, pf = 60 * deg;
  const double w = 0.5 * 25e3 * h * h * ((1 - (z / h) * (z / h)) / std::tan(pp) - 1 / std::tan(pf));
  const double a = (h - z) / std::sin(pp);
  const double u = 0.5 * 9810.0 * water_depth * a, v = 0.5 * 9810.0 * water_depth * water_depth;
  return (20e3 * a +
          (w * (std::cos(pp) - kh * std::sin(pp)) - u - v * std::sin(pp)) * std::tan(35 * deg)) /
         (w * (std::sin(pp) + kh * std::cos(pp)) + v * std::cos(pp));
}

TEST(SlopeStabilityExample, FactorsOfSafetyBracketHoekAndBray) {
  const struct {
    const char* file;
    double expected;
  } cases[] = {{"dry.yaml", hoek_bray(0.0, 0.0)},
               {"water.yaml", hoek_bray(3.0, 0.0)},
               {"seismic.yaml", hoek_bray(0.0, 0.1)}};
  for (const auto& c : cases) {
    const fs::path out = run_example(std::string("slope_stability/") + c.file);
    const nlohmann::json s = testing::read_json(out / "summary.json");
    const nlohmann::json& f = s.at("factor_of_safety");
    const double lower = f.at("lower").get<double>(), upper = f.at("upper").get<double>();
    // The bracket holds F to its tolerance, 1e-4, and to the 4 decimals of the vertices.
    EXPECT_LE(lower, c.expected * (1 + 1e-5)) << c.file;
    EXPECT_GE(upper, c.expected * (1 - 1e-5)) << c.file;
    EXPECT_LE(upper - lower, 1.1e-4 * upper) << c.file;
    // The sliding block is the mechanism's fastest (fos_mechanism.csv: its speed is 1; the
    // blocks around it move only elastically, a few percent of it).
    const std::string csv = testing::read_text(out / "fos_mechanism.csv");
    const std::size_t row = csv.find("\n0,");
    ASSERT_NE(row, std::string::npos) << csv;
    const std::string line = csv.substr(row + 1, csv.find('\n', row + 1) - row - 1);
    EXPECT_TRUE(line.ends_with(",1,moves")) << line;
    EXPECT_TRUE(fs::exists(out / "fos_mechanism.png"));
    EXPECT_TRUE(fs::exists(out / "fos_trials.svg"));
  }
}

// The tunnel (examples/tunnel_excavation): the in-situ stress balances the first stage's loads
// (virtual work, block by block: round-off), each excavation removes the blocks of its zone
// (blocks.csv's materials), the crown settles and the floor heaves as the heading's forces are
// released, linearly while no joint yields (half the release, half the displacement), and the
// bench's release ends in a proven collapse with its mechanism drawn.
TEST(Examples, TheTunnelIsExcavatedFromItsInSituStressUntilAWedgeFallsFromTheCrown) {
  const fs::path out = run_example("tunnel_excavation/case.yaml");
  const nlohmann::json s = testing::read_json(out / "summary.json");
  EXPECT_LT(s.at("initial_stress").at("relative_residual").get<double>(), 1e-12);
  EXPECT_EQ(s.at("initial_stress").at("violated_points").get<int>(), 0);

  std::map<std::string, std::vector<int>> of_material;
  std::ifstream blocks(out / "blocks.csv");
  std::string line;
  std::getline(blocks, line);
  while (std::getline(blocks, line)) {
    const std::size_t comma = line.find(',');
    const std::size_t next = line.find(',', comma + 1);
    of_material[line.substr(comma + 1, next - comma - 1)].push_back(
        std::stoi(line.substr(0, comma)));
  }
  const nlohmann::json& stages = s.at("stages");
  ASSERT_EQ(stages.size(), 4u);
  EXPECT_EQ(stages[1].at("excavated_blocks").get<std::vector<int>>(), of_material["heading"]);
  EXPECT_EQ(stages[1].at("release").get<double>(), 0.5);
  EXPECT_EQ(stages[3].at("excavated_blocks").get<std::vector<int>>(), of_material["bench"]);
  // K once, and again after each of the two stages that excavate (condensations besides).
  EXPECT_GE(s.at("factorizations").at("stiffness").get<int>(), 3);

  // history.csv: the crown's and the floor's vertical displacement after each step.
  std::ifstream history(out / "history.csv");
  std::getline(history, line);
  std::vector<std::vector<std::string>> rows;
  while (std::getline(history, line)) {
    std::vector<std::string> cells;
    std::size_t at = 0;
    for (std::size_t comma; (comma = line.find(',', at)) != std::string::npos; at = comma + 1)
      cells.push_back(line.substr(at, comma - at));
    cells.push_back(line.substr(at));
    rows.push_back(cells);
  }
  ASSERT_GE(rows.size(), 9u);
  // Columns: stage, stage_name, increment, stage_factor, point_load_N, ux_crown_m, uy_crown_m,
  // ux_wall_m, uy_wall_m, ux_floor_m, uy_floor_m, yielding_points, ...
  const auto value = [&](std::size_t row, std::size_t column) {
    return std::stod(rows[row][column]);
  };
  EXPECT_LT(std::abs(value(0, 6)), 1e-15);  // in situ: nothing moves
  EXPECT_LT(value(2, 6), 0.0);              // the crown settles
  EXPECT_GT(value(2, 10), 0.0);             // the floor heaves
  EXPECT_EQ(value(2, 11), 0.0);             // no joint yields yet: elastic, linear in the release
  EXPECT_NEAR(value(2, 6), 2.0 * value(1, 6), 1e-9 * std::abs(value(2, 6)));
  EXPECT_NEAR(value(2, 10), 2.0 * value(1, 10), 1e-9 * std::abs(value(2, 10)));

  const nlohmann::json& collapse = s.at("collapse");
  ASSERT_FALSE(collapse.is_null());
  EXPECT_EQ(collapse.at("stage").get<std::string>(), "bench");
  EXPECT_TRUE(fs::exists(out / "collapse.png"));
  EXPECT_TRUE(fs::exists(out / "final.png"));
}

}  // namespace
}  // namespace bimrock
