// The load-displacement plots draw (and name on their axis) the direction of the last stage's
// load: the resultant of its loads, whatever they are (a surcharge is a traction, not a point
// load), or the controlled direction. Expected: the directions worked out from each case by hand.
#include <string>

#include <gtest/gtest.h>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/history_writer.hpp>

namespace bimrock {
namespace {

// Two blocks on a fixed base, gravity, then a stage of `loads` (SI units).
std::string two_blocks_with_stage(const std::string& stage) {
  return R"(schema: 1
materials:
  rock: {E: 10.0e9, nu: 0.2, unit_weight: 20.0e3}
joint_materials:
  joint: {kn: 1.0e10, ks: 1.0e10, cohesion: 1.0e5, friction: 30}
joints: {default: joint}
supports:
  - {line: [[0, 0], [2, 0]], type: fixed}
monitors:
  - {name: top, at: [1.5, 1.0]}
blocks:
  - {material: rock, vertices: [[0, 0], [1, 0], [1, 1], [0, 1]]}
  - {material: rock, vertices: [[1, 0], [2, 0], [2, 1], [1, 1]]}
stages:
  - name: gravity
    loads: {gravity: [0, -1]}
)" + stage;
}

// The direction the last stage's curves are drawn along.
Vec2 direction(const std::string& case_text) {
  const Case c = read_case_string(case_text, "case.yaml");
  const Model model = build_model(c.spec);
  return plotted_direction(model, model.stages.back());
}

void expect_direction(const Vec2& d, double x, double y) {
  EXPECT_NEAR(d.x(), x, 1e-12);
  EXPECT_NEAR(d.y(), y, 1e-12);
}

TEST(HistoryPlot, ASurchargeIsDrawnDownwardsAndSaysSo) {
  // The traction's resultant is 1e5 Pa x 2 m downwards; the stage has no weight of its own.
  expect_direction(direction(two_blocks_with_stage(R"(  - name: surcharge
    increments: 3
    loads:
      tractions:
        - {line: [[0, 1], [2, 1]], normal: -1.0e5}
)")),
                   0.0, -1.0);
}

TEST(HistoryPlot, APointLoadAndAControlledDirectionAreDrawnAlongThemselves) {
  expect_direction(direction(two_blocks_with_stage(R"(  - name: push
    increments: 3
    loads:
      points:
        - {at: [1.5, 0.5], force: [3.0e4, 4.0e4]}
)")),
                   0.6, 0.8);  // (3, 4) / 5
  expect_direction(direction(two_blocks_with_stage(R"(  - name: push
    increments: 3
    control: {monitor: top, direction: [2, 0], displacement: 1.0e-6}
    loads:
      points:
        - {at: [1.5, 0.5], force: [3.0e4, 4.0e4]}
)")),
                   1.0, 0.0);
}

}  // namespace
}  // namespace bimrock
