#include <bimrock/reference/reference_cases.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <bimrock/geometry/brick_pattern.hpp>

namespace bimrock {

namespace {

BlockMaterial granite() {
  BlockMaterial rock;
  rock.name = "rock";
  rock.young = 89e9;
  rock.poisson = 0.26;
  rock.unit_weight = 26e3;
  rock.source.item = "materials.rock";
  return rock;
}

JointMaterial example1_joint() {
  JointMaterial joint;
  joint.name = "joint";
  joint.normal_stiffness = 531.9e9;
  joint.shear_stiffness = 438.8e9;
  joint.source.item = "joint_materials.joint";
  return joint;
}

Selector line(Vec2 a, Vec2 b, const std::string& item) {
  Selector s;
  s.kind = Selector::Kind::line;
  s.line = {a, b};
  s.source.item = item;
  return s;
}

void add_blocks(CaseSpec& c, const std::vector<Polygon>& polygons) {
  for (std::size_t k = 0; k < polygons.size(); ++k)
    c.blocks.push_back({polygons[k], "rock", {0, "blocks[" + std::to_string(k) + "]"}});
}

}  // namespace

CaseSpec brick_mass_case(int n_blocks) {
  const int side = std::max(2, static_cast<int>(std::lround(std::sqrt(double(n_blocks)))));
  const double size = 0.2;
  CaseSpec c;
  c.file = "brick_mass(" + std::to_string(n_blocks) + ")";
  c.block_materials = {granite()};
  c.joint_materials = {example1_joint()};
  add_blocks(c, brick_pattern(side, side, size, size, Stagger::rows));
  c.default_joint = "joint";
  c.supports.push_back(
      {line({0, 0}, {side * size, 0}, "base"), SupportKind::fixed, std::nullopt, {0, "base"}});
  c.loads.gravity = Vec2(0, -1);
  return c;
}

namespace {
constexpr double kWallCohesion = 50e3;
constexpr double kWallFriction = 35.0 * M_PI / 180.0;
constexpr double kBrickHeight = 0.2;
}  // namespace

double wall_collapse_shear() {
  return kWallCohesion + 26e3 * kBrickHeight * std::tan(kWallFriction);
}

CaseSpec wall_case(int n_blocks, int increments, double shear) {
  const double bw = 0.4, bh = kBrickHeight;
  const int ny = std::max(2, static_cast<int>(std::lround(std::sqrt(n_blocks / 2.0))));
  const int nx = 2 * ny;  // 0.8 m of width per row: four times as wide as high
  const double width = nx * bw, height = ny * bh;
  CaseSpec c;
  c.file = "wall(" + std::to_string(n_blocks) + ")";
  c.block_materials = {granite()};
  JointMaterial joint = example1_joint();
  JointStrength s;
  s.cohesion = Softening::constant(kWallCohesion);
  s.friction = Softening::constant(std::tan(kWallFriction));
  s.dilation = std::tan(kWallFriction);
  s.tensile = Softening::constant(50e3);
  joint.strength = s;
  c.joint_materials = {joint};
  add_blocks(c, brick_pattern(nx, ny, bw, bh, Stagger::rows));
  c.default_joint = "joint";
  c.supports.push_back(
      {line({0, 0}, {width, 0}, "base"), SupportKind::fixed, std::nullopt, {0, "base"}});
  c.monitors.push_back({"top", Vec2(width, height), {0, "monitors[0]"}});
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0, -1);
  StageSpec push{"push", {}, increments, std::nullopt, {0, "stages[1]"}};
  // On the top edge (outward normal +y) the tangent s = (-n_y, n_x) = (-1, 0): a negative shear
  // pushes in +x.
  push.loads.tractions.push_back(
      {line({0, height}, {width, height}, "top"), 0.0, -shear, {0, "top"}});
  c.stages = {gravity, push};
  return c;
}

namespace {
constexpr double kAbutmentCohesion = 50e3;
constexpr double kAbutmentFriction = 35.0 * M_PI / 180.0;
constexpr double kAbutmentTension = 50e3;
constexpr double kAbutmentWidth = 2.0;     // [m] of the loaded strip
constexpr double kAbutmentSetback = 2.0;   // [m] from the strip to the cliff
constexpr double kPressurePerShear = 0.5;  // the thrust's normal over its shear component
}  // namespace

double abutment_collapse_shear() {
  // The top row from the strip's inner end to the cliff slides on its bed joint and tears off
  // its vertical joint at the strip's inner end (tension), pushed by tau B and held down by its
  // weight and the pressure (docs/formulation.md: the joint law): tau B = c L + sigma_t h + (gamma
  // h L + kPressurePerShear tau B) tan(phi).
  const double b = kAbutmentWidth, l = kAbutmentWidth + kAbutmentSetback, h = kBrickHeight;
  const double t = std::tan(kAbutmentFriction);
  return (kAbutmentCohesion * l + kAbutmentTension * h + 26e3 * h * l * t) /
         (b * (1.0 - kPressurePerShear * t));
}

CaseSpec abutment_case(int n_blocks, int increments, double shear, JointFlow flow) {
  const double size = kBrickHeight;
  const int ny = std::max(2, static_cast<int>(std::lround(std::sqrt(n_blocks / 2.0))));
  const int nx = std::max(
      2 * ny, static_cast<int>(std::ceil(2.0 * (kAbutmentWidth + kAbutmentSetback) / size)));
  const double width = nx * size, height = ny * size;
  CaseSpec c;
  c.file = "abutment(" + std::to_string(n_blocks) + ")";
  c.block_materials = {granite()};
  JointMaterial joint = example1_joint();
  JointStrength s;
  s.cohesion = Softening::constant(kAbutmentCohesion);
  s.friction = Softening::constant(std::tan(kAbutmentFriction));
  s.dilation = flow == JointFlow::associated ? std::tan(kAbutmentFriction) : 0.0;
  s.tensile = Softening::constant(kAbutmentTension);
  joint.strength = s;
  c.joint_materials = {joint};
  add_blocks(c, brick_pattern(nx, ny, size, size, Stagger::rows));
  c.default_joint = "joint";
  c.supports.push_back(
      {line({0, 0}, {width, 0}, "base"), SupportKind::fixed, std::nullopt, {0, "base"}});
  c.supports.push_back(
      {line({0, 0}, {0, height}, "left"), SupportKind::roller, std::nullopt, {0, "left"}});
  // The strip [x0, x1] on the top, its ends on multiples of the block size (corners of the top
  // row whether or not it is shifted).
  const double x1 = width - kAbutmentSetback, x0 = x1 - kAbutmentWidth;
  c.monitors.push_back({"abutment", Vec2(x1, height), {0, "monitors[0]"}});
  StageSpec gravity{"gravity", {}, 1, std::nullopt, {0, "stages[0]"}};
  gravity.loads.gravity = Vec2(0, -1);
  StageSpec load{"thrust", {}, increments, std::nullopt, {0, "stages[1]"}};
  // On the top edge (outward normal +y) the tangent s = (-n_y, n_x) = (-1, 0): a negative shear
  // pushes towards the cliff (+x).
  load.loads.tractions.push_back({line({x0, height}, {x1, height}, "abutment"),
                                  -kPressurePerShear * shear,
                                  -shear,
                                  {0, "abutment"}});
  c.stages = {gravity, load};
  return c;
}

}  // namespace bimrock
