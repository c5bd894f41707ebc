#pragma once
/// @file What a case file says, before it is turned into a Model: names not yet resolved,
/// selectors not yet applied. The io layer fills it; build_model() checks and resolves it.
/// Units: SI throughout (m, Pa, Pa/m, N, N/m^3).
#include <optional>
#include <string>
#include <vector>

#include <map>

#include <bimrock/geometry/domain.hpp>
#include <bimrock/geometry/joint_set.hpp>
#include <bimrock/geometry/polygon.hpp>
#include <bimrock/geometry/voronoi_subdivision.hpp>
#include <bimrock/model/materials.hpp>
#include <bimrock/model/selector.hpp>

namespace bimrock {

struct AnalysisSettings {
  PlaneMode plane = PlaneMode::strain;
  double thickness = 1.0;  ///< t [m]
  /// Penalty factor for continuum interfaces and rigid supports without their own material.
  double penalty_factor = kDefaultPenaltyFactor;
};

struct BlockSpec {
  Polygon polygon;
  std::string material;
  SourceRef source;
};

/// Interfaces picked by `where` get joint material `material`; later rules win.
struct JointRule {
  Selector where;
  std::string material;
  SourceRef source;
};

enum class SupportKind {
  fixed,   ///< both directions held
  roller,  ///< normal direction held, free to slide along the edge
};

/// Boundary edges picked by `where` are tied to the fixed ground.
struct SupportSpec {
  Selector where;
  SupportKind kind = SupportKind::fixed;
  std::optional<std::string> joint_material;  ///< springs of the support; default: rigid penalty
  SourceRef source;
};

struct PointLoadSpec {
  Vec2 point = Vec2::Zero();  ///< [m], must lie in a block
  Vec2 force = Vec2::Zero();  ///< [N] over the thickness t
  SourceRef source;
};

/// Traction on the boundary edges picked by `where`.
struct TractionSpec {
  Selector where;
  double normal = 0.0;  ///< [Pa] along the outward normal: positive pulls (tension positive)
  double shear =
      0.0;  ///< [Pa] along the tangent s = (-n_y, n_x) (counter-clockwise round the block)
  SourceRef source;
};

/// A prescribed water pressure along a straight line (a tension crack, an uplift distribution):
/// linear from `pressure_from` at `from` to `pressure_to` at `to`, on every wet block face that
/// lies on the segment.
struct PressureLineSpec {
  Vec2 from = Vec2::Zero();
  Vec2 to = Vec2::Zero();
  double pressure_from = 0.0;  ///< [Pa], compression positive
  double pressure_to = 0.0;    ///< [Pa]
  SourceRef source;
};

/// Water in the joints (docs/formulation.md, "Water"): hydrostatic below a phreatic surface,
/// and prescribed pressure lines, which replace it where they lie.
struct WaterSpec {
  std::vector<Vec2> surface;    ///< the phreatic surface [m], x increasing; empty: none
  double unit_weight = 9810.0;  ///< [N/m^3]
  std::vector<PressureLineSpec> lines;
  SourceRef source;
};

struct LoadsSpec {
  /// Body force per unit volume = unit_weight * gravity (gravity is dimensionless, e.g. (0, -1)).
  Vec2 gravity = Vec2::Zero();
  std::vector<PointLoadSpec> points;
  std::vector<TractionSpec> tractions;
  /// The water at the end of the stage; it replaces the earlier stages' water, not adds to it.
  std::optional<WaterSpec> water;
};

struct MonitorSpec {
  std::string name;
  Vec2 point = Vec2::Zero();
  SourceRef source;
};

/// Load control scales the stage's loads by the load factor; displacement control instead
/// prescribes the displacement of a monitor point along `direction` and finds the load factor
/// (it follows softening past the peak).
struct DisplacementControlSpec {
  std::string monitor;
  Vec2 direction = Vec2::UnitX();
  double displacement = 0.0;  ///< total over the stage [m]
  SourceRef source;
};

/// Choosing blocks (stages' `excavate` and `install`): those whose centroid lies in a region
/// (a polygon) or a box, those of a block material, or a list of block indices.
struct BlockSelector {
  enum class Kind { region, box, material, list };
  Kind kind = Kind::region;
  Polygon region;           ///< kind region [m]
  BBox box;                 ///< kind box [m]
  std::string material;     ///< kind material: a block material's name
  std::vector<int> blocks;  ///< kind list: indices in the model's order of blocks
  SourceRef source;
};

/// A load stage of a nonlinear analysis: its loads are added to those of the earlier stages in
/// `increments` equal steps; stresses and plastic state carry from one stage into the next.
/// A stage can also excavate blocks (the forces they exerted on the others are released over
/// its increments, `release` of them in this stage and the rest in the next) and install blocks
/// absent until then.
struct StageSpec {
  std::string name;
  LoadsSpec loads;
  int increments = 1;
  std::optional<DisplacementControlSpec> control;
  SourceRef source;
  // After `source`, with initializers: positional initializations of the fields above still hold.
  std::optional<BlockSelector> excavate{};
  std::optional<BlockSelector> install{};
  double release = 1.0;  ///< fraction of the unreleased excavation forces released, (0, 1]
};

/// The stress in the rock before the first stage (docs/case-file.md, "Initial stress"): a
/// uniform part plus, if given, a gravitational one, sigma_yy = -unit_weight * (ground_level -
/// y) below the ground level (0 above it) and sigma_xx = k0 * sigma_yy. Tension positive [Pa].
struct InitialStressSpec {
  Eigen::Vector3d uniform = Eigen::Vector3d::Zero();  ///< [sigma_xx, sigma_yy, tau_xy] [Pa]
  struct Gravity {
    double ground_level = 0.0;  ///< y of the ground surface [m]
    double unit_weight = 0.0;   ///< [N/m^3]
    double k0 = 1.0;            ///< horizontal / vertical stress
  };
  std::optional<Gravity> gravity;
  bool allow_yield = false;  ///< points that violate their strength yield in the first stage
  SourceRef source;
};

/// A rock bolt or anchor (docs/case-file.md, "Bolts"): a bar from its head `from` to its far end
/// `to`, installed at the start of a stage. An anchored bolt is fixed at both ends and free
/// between them: one spring from head to anchor, with the stiffness of its free length. A grouted
/// bolt is bonded along its length: a spring at each joint it crosses. Each spring carries an
/// axial force up to the tensile capacity, and, if a shear stiffness is given, a shear force
/// (up to the shear capacity, if given). Forces and stiffnesses are those of one bolt; bolts
/// repeat along the model's out-of-plane direction at `spacing`.
struct BoltSpec {
  enum class Kind { anchored, grouted };
  std::string name;  ///< empty: "bolt <index>"
  Kind kind = Kind::anchored;
  Vec2 from = Vec2::Zero();      ///< the head A [m]
  Vec2 to = Vec2::Zero();        ///< the far end B [m]
  double axial_stiffness = 0.0;  ///< [N/m]: of the free length (anchored), at each joint (grouted)
  double capacity = 0.0;         ///< tensile capacity [N]
  double pretension = 0.0;       ///< [N], anchored bolts only
  double shear_stiffness = 0.0;  ///< [N/m], 0: the bolt carries no shear
  std::optional<double> shear_capacity;  ///< [N]; none: the shear stays elastic
  std::optional<double> spacing;         ///< out-of-plane [m]; none: the model's thickness
  std::string install;                   ///< the stage's name; empty: the first stage
  SourceRef source;
  std::map<std::string, int> lines;  ///< the line of each key ("bolts[2].to"), for errors
};

/// Blocks cut from a rock domain by joint sets (the case file's `domain`), instead of listed.
struct DomainSpec {
  Domain domain;                     ///< outline, holes, zones (each naming its block material)
  std::string material;              ///< block material outside every zone
  std::vector<JointSet> joint_sets;  ///< each names its joint material
  std::vector<Joint> joints;         ///< individual joints
  /// Joint material of the cuts through intact rock (rock bridges, convex partitions, zone
  /// contacts, subdivision cells); empty: continuum (penalty) interfaces.
  std::string intact;
  std::optional<double> min_block_area;       ///< [m^2]; default suggested_min_block_area()
  std::optional<VoronoiOptions> subdivision;  ///< split blocks larger than target_size^2
  SourceRef source;
  std::map<std::string, int> lines;  ///< the line of each item ("domain.holes[1]"), for errors
};

/// A physical surface of a mesh and the block material of its cells (`mesh.materials`).
struct MeshMaterialSpec {
  std::string group;
  std::string material;
  SourceRef source;
};

/// Blocks imported from a mesh (the case file's `mesh`): one block per cell, its
/// material from its physical surface; the cells are joined by `interfaces`.
struct MeshSpec {
  std::string file;                         ///< the mesh file, as read (for messages)
  std::vector<BlockSpec> cells;             ///< one per cell, in the file's order
  std::vector<MeshMaterialSpec> materials;  ///< physical surface -> block material
  /// Joint material between cells; empty: continuum (penalty) interfaces.
  std::string interfaces;
  SourceRef source;
};

/// Bounds on what a case may generate (the case file's `limits`), checked against an estimate
/// before the work that would exceed them starts, so that a mistyped spacing or count is refused
/// with a message instead of exhausting memory, disk or time. A case may raise them.
struct CaseLimits {
  double blocks = 1e6;               ///< blocks, listed or generated (cut blocks and Voronoi cells)
  double joint_traces = 1e6;         ///< traces generated by the joint sets
  double interfaces = 1e7;           ///< interface segments after subdivision, supports included
  double yield_planes = 1e7;         ///< linearized block-strength planes, summed over the blocks
  double increments = 1e5;           ///< load increments, summed over the stages
  double output_mb = 1e4;            ///< estimated size of the results [MB]
  std::map<std::string, int> lines;  ///< the line of each given limit ("limits.blocks"), for errors
};

struct CaseSpec {
  std::string file;  ///< the case file, for error messages
  std::string title;
  AnalysisSettings settings;
  std::vector<BlockMaterial> block_materials;
  std::vector<JointMaterial> joint_materials;
  std::vector<BlockSpec> blocks;
  std::optional<DomainSpec> domain;  ///< blocks generated from a domain (then `blocks` is empty)
  std::optional<MeshSpec> mesh;      ///< blocks imported from a mesh (then `blocks` is empty)
  std::string default_joint;         ///< joint material of interfaces no rule picks
  std::vector<JointRule> joint_rules;
  std::vector<SupportSpec> supports;
  LoadsSpec loads;                ///< the loads of an elastic analysis (no stages)
  std::vector<StageSpec> stages;  ///< a nonlinear analysis when not empty
  std::optional<InitialStressSpec> initial_stress;  ///< stages only
  std::vector<BoltSpec> bolts;                      ///< stages only
  std::vector<MonitorSpec> monitors;
  CaseLimits limits;
};

}  // namespace bimrock
