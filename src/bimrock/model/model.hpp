#pragma once
/// @file The block-interfaces model as plain data, checked once when built (build_model).
/// Units: SI throughout (m, Pa, Pa/m, N, N/m^3).
#include <optional>
#include <string>
#include <vector>

#include <bimrock/geometry/polygon.hpp>
#include <bimrock/geometry/shared_edges.hpp>
#include <bimrock/model/case_spec.hpp>

namespace bimrock {

/// The index a support interface uses for the fixed ground in place of block j.
inline constexpr int kGround = -1;

struct Block {
  Polygon polygon;
  Vec2 centroid;  ///< (x0, y0) of eq. 1
  double area = 0.0;
  int material = 0;  ///< index into Model::block_materials
  SourceRef source;
};

/// A straight segment of contact between block i and block j (or the ground, j == kGround).
struct Interface {
  int block_i = 0;
  int block_j = kGround;
  Segment segment;
  Vec2 normal;  ///< unit, from i into j; delta_n > 0 is opening (docs/formulation.md)
  double normal_stiffness = 0.0;  ///< k_n [Pa/m]
  double shear_stiffness = 0.0;   ///< k_s [Pa/m]
  Integration integration = Integration::lobatto;
  int joint_material = -1;  ///< index into Model::joint_materials; -1 for a rigid (penalty) support
  int support = -1;         ///< index of the support spec for ground interfaces, else -1

  [[nodiscard]] bool is_support() const { return block_j == kGround; }
};

struct PointLoad {
  int block = 0;
  Vec2 point;
  Vec2 force;  ///< [N]
};

struct Traction {
  int block = 0;
  Segment segment;
  Vec2 outward_normal;
  double normal = 0.0;  ///< [Pa], tension positive
  double shear = 0.0;   ///< [Pa], along (-n_y, n_x)
};

/// Water pressure on a piece of a block's face, linear from `pressure_a` at segment.a to
/// `pressure_b` at segment.b, pushing into the block (compression positive; a stage that lowers
/// the water holds negative pressures: the change).
struct PressureFace {
  int block = 0;
  Segment segment;
  Vec2 outward_normal;
  double pressure_a = 0.0;  ///< [Pa]
  double pressure_b = 0.0;  ///< [Pa]
};

struct Loads {
  Vec2 gravity = Vec2::Zero();  ///< body force per volume = unit_weight * gravity
  std::vector<PointLoad> points;
  std::vector<Traction> tractions;
  std::vector<PressureFace> water;  ///< model/water_pressure.hpp
  std::vector<Vec2> water_surface;  ///< the phreatic surface in force after these loads, to draw
};

struct DisplacementControl {
  int monitor = 0;                 ///< index into Model::monitors
  Vec2 direction = Vec2::UnitX();  ///< unit
  double displacement = 0.0;       ///< total over the stage [m]
};

struct Stage {
  std::string name;
  Loads loads;  ///< added to the loads of earlier stages, in `increments` equal steps
  int increments = 1;
  std::optional<DisplacementControl> control;
  SourceRef source;
  // After `source`, with initializers: positional initializations of the fields above still hold.
  /// Blocks removed at the stage's start (present until then), sorted.
  std::vector<int> excavated{};
  /// Blocks added at the stage's start (absent until then), sorted.
  std::vector<int> installed{};
  double release = 1.0;  ///< fraction of the unreleased excavation forces released here
};

/// A rock bolt or anchor (BoltSpec, resolved): its springs are Model::bolt_springs.
struct Bolt {
  std::string name;
  BoltSpec::Kind kind = BoltSpec::Kind::anchored;
  Vec2 from = Vec2::Zero();  ///< head [m]
  Vec2 to = Vec2::Zero();    ///< far end [m]
  double axial_stiffness = 0.0;          ///< per spring [N/m]
  double shear_stiffness = 0.0;          ///< per spring [N/m]
  double capacity = 0.0;                 ///< tensile [N]
  std::optional<double> shear_capacity;  ///< [N]; none: elastic in shear
  double pretension = 0.0;               ///< [N]
  double per_model = 1.0;  ///< bolts in the model's thickness: thickness / spacing
  int stage = 0;           ///< installed at this stage's start
  SourceRef source;
};

/// One spring of a bolt (docs/formulation.md, "Bolts"): it joins point `a` of block `block_a`
/// to point `b` of block `block_b` along `axis` (unit, from the bolt's head towards its far end);
/// its relative displacement is delta = T(axis) (Q_b(b) d_b - Q_a(a) d_a), its elongation first.
/// An anchored bolt has one, from head to anchor; a grouted bolt one at each joint it crosses
/// (a == b there), between the blocks on either side.
struct BoltSpring {
  int bolt = 0;  ///< index into Model::bolts
  int block_a = 0;
  int block_b = 0;
  Vec2 a = Vec2::Zero();
  Vec2 b = Vec2::Zero();
  Vec2 axis = Vec2::UnitX();
};

struct Monitor {
  std::string name;
  int block = 0;
  Vec2 point;
};

struct Model {
  std::string source_file;
  std::string title;
  AnalysisSettings settings;
  std::vector<BlockMaterial> block_materials;
  std::vector<JointMaterial> joint_materials;
  std::vector<Block> blocks;
  std::vector<Interface> interfaces;   ///< block-block interfaces first, then supports
  std::vector<BoundaryEdge> boundary;  ///< the outline (supported parts included)
  Loads loads;                         ///< of an elastic analysis
  std::vector<Stage> stages;           ///< of a nonlinear analysis
  std::vector<Monitor> monitors;
  std::optional<InitialStressSpec> initial_stress;  ///< model/initial_stress.hpp
  std::vector<Bolt> bolts;                          ///< model/bolts.hpp
  std::vector<BoltSpring> bolt_springs;             ///< by bolt, head to far end
  double tolerance = 0.0;                           ///< length tolerance, see model_tolerance()

  [[nodiscard]] int n_blocks() const { return static_cast<int>(blocks.size()); }
  [[nodiscard]] int n_interfaces() const { return static_cast<int>(interfaces.size()); }
  [[nodiscard]] int n_dofs() const { return 6 * n_blocks(); }
};

/// Checks the case and resolves it into a Model: polygons valid, blocks not overlapping,
/// materials known and physical, interfaces detected and given their springs, supports,
/// loads and monitors attached to blocks. Throws InputError naming the offending item.
/// Whether the supports hold every block is checked by the analysis (it needs K).
Model build_model(const CaseSpec& spec);

/// The model of `spec` on the geometry of `built` (its blocks, interfaces and outline), which
/// build_model() made from a spec with the same blocks (or domain or mesh), joints and supports:
/// only the materials, the interfaces' springs, the loads, the monitors and the stages are made
/// anew, so that a study that varies those pays for its analyses only. The materials must keep
/// the built model's names, order and subdivisions. Throws InputError as build_model() does.
Model rebuild_model(const Model& built, const CaseSpec& spec);

/// Index of the block containing p (within tol), or -1. Linear scan: for a few points only.
int find_block_containing(const Model& model, const Vec2& p);

}  // namespace bimrock
