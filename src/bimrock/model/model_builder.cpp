#include <algorithm>
#include <cmath>
#include <map>

#include <bimrock/model/block_generation.hpp>
#include <bimrock/model/bolts.hpp>
#include <bimrock/model/limits.hpp>
#include <bimrock/model/model.hpp>
#include <bimrock/model/stage_blocks.hpp>
#include <bimrock/model/water_pressure.hpp>

namespace bimrock {
namespace {

std::string quoted(const std::string& s) {
  return "'" + s + "'";
}

bool finite_positive(double x) {
  return std::isfinite(x) && x > 0.0;
}
bool finite_non_negative(double x) {
  return std::isfinite(x) && x >= 0.0;
}

class Builder {
 public:
  explicit Builder(const CaseSpec& spec) : spec_(spec) {}

  Model build() {
    model_.source_file = spec_.file;
    model_.title = spec_.title;
    check_settings();
    add_materials();
    if (spec_.domain) {
      if (!spec_.blocks.empty())
        fail(spec_.domain->source, "give either blocks or a domain, not both");
      generated_ = generate_blocks(*spec_.domain, spec_.file, spec_.limits);
    }
    if (spec_.mesh)
      check_mesh();
    add_blocks();
    add_interfaces();
    add_supports();
    locate_points();
    add_loads();
    add_monitors();
    add_stages();
    return std::move(model_);
  }

  // The spec's materials, springs, loads, monitors and stages on the blocks, interfaces and
  // outline of `built`, whose spec had the same blocks, joints and supports: the geometry, the
  // costly part, is not made again.
  Model rebuild(const Model& built) {
    model_.source_file = spec_.file;
    model_.title = spec_.title;
    model_.blocks = built.blocks;
    model_.interfaces = built.interfaces;
    model_.boundary = built.boundary;
    model_.tolerance = built.tolerance;
    check_settings();
    add_materials();
    check_same_materials(built);
    for (Interface& f : model_.interfaces) {
      const SpringPair k_ns = springs(f.joint_material, f.block_i, f.block_j);
      f.normal_stiffness = k_ns.normal;
      f.shear_stiffness = k_ns.shear;
      if (f.support >= 0) {
        if (f.support >= static_cast<int>(spec_.supports.size()))
          fail({0, "supports"}, "the supports differ from the built model's: build a new model");
        if (spec_.supports[static_cast<std::size_t>(f.support)].kind == SupportKind::roller)
          f.shear_stiffness = 0.0;
      }
    }
    polygons_.reserve(model_.blocks.size());
    for (const Block& b : model_.blocks)
      polygons_.push_back(b.polygon);
    locate_points();
    add_loads();
    add_monitors();
    add_stages();
    return std::move(model_);
  }

 private:
  [[noreturn]] void fail(const SourceRef& ref, const std::string& message) const {
    throw InputError(spec_.file, ref, message);
  }

  void check_settings() {
    const AnalysisSettings& s = spec_.settings;
    if (!finite_positive(s.thickness))
      fail({0, "analysis.thickness"}, "thickness must be a positive number");
    if (!finite_positive(s.penalty_factor))
      fail({0, "analysis.penalty_factor"}, "penalty factor must be a positive number");
    model_.settings = s;
  }

  void add_materials() {
    for (const BlockMaterial& m : spec_.block_materials) {
      if (block_material_index_.count(m.name))
        fail(m.source, "duplicate material name");
      if (!finite_positive(m.young))
        fail(m.source, "Young's modulus E must be positive");
      if (!std::isfinite(m.poisson) || m.poisson <= -1.0 || m.poisson >= 0.5)
        fail(m.source, "Poisson's ratio nu must lie in (-1, 0.5)");
      if (!finite_non_negative(m.unit_weight))
        fail(m.source, "unit weight must be >= 0");
      block_material_index_[m.name] = static_cast<int>(model_.block_materials.size());
      model_.block_materials.push_back(m);
    }
    for (const JointMaterial& j : spec_.joint_materials) {
      if (joint_material_index_.count(j.name))
        fail(j.source, "duplicate joint material name");
      if (j.kind == JointMaterial::Kind::springs) {
        if (!finite_positive(j.normal_stiffness))
          fail(j.source, "normal stiffness k_n must be positive");
        if (!finite_non_negative(j.shear_stiffness))
          fail(j.source, "shear stiffness k_s must be >= 0");
      } else if (!finite_positive(j.penalty_factor)) {
        fail(j.source, "penalty factor must be positive");
      }
      if (j.subdivisions < 1)
        fail(j.source, "subdivisions must be at least 1");
      joint_material_index_[j.name] = static_cast<int>(model_.joint_materials.size());
      model_.joint_materials.push_back(j);
    }
  }

  // The blocks and interfaces of a built model refer to its materials by index, and its
  // interfaces were split by their joint material's subdivisions: a rebuild keeps the names, their
  // order and the subdivisions (the intact rock's continuum material, added by the builder, again).
  void check_same_materials(const Model& built) {
    const auto& blocks = model_.block_materials;
    const auto& before = built.block_materials;
    if (blocks.size() != before.size())
      fail({0, "materials"}, "gives other materials than the built model's: build a new model");
    for (std::size_t k = 0; k < blocks.size(); ++k) {
      if (blocks[k].name != before[k].name)
        fail(blocks[k].source, "is not the built model's material " + quoted(before[k].name) +
                                   " (keep the names and their order, or build a new model)");
    }
    const std::size_t given = model_.joint_materials.size();
    if (given + 1 == built.joint_materials.size() &&
        built.joint_materials.back().kind == JointMaterial::Kind::continuum)
      intact_material("", built.joint_materials.back().source);
    const auto& joints = model_.joint_materials;
    const auto& joints_before = built.joint_materials;
    if (joints.size() != joints_before.size())
      fail({0, "joint_materials"},
           "gives other joint materials than the built model's: build a new model");
    for (std::size_t k = 0; k < joints.size(); ++k) {
      if (joints[k].name != joints_before[k].name)
        fail(joints[k].source, "is not the built model's joint material " +
                                   quoted(joints_before[k].name) +
                                   " (keep the names and their order, or build a new model)");
      if (joints[k].subdivisions != joints_before[k].subdivisions ||
          joints[k].integration != joints_before[k].integration)
        fail(joints[k].source,
             "changes the subdivisions or the integration of the interfaces: build a new model");
    }
  }

  // A mesh stands instead of blocks or a domain; each physical surface names a known material.
  void check_mesh() const {
    if (!spec_.blocks.empty() || spec_.domain)
      fail(spec_.mesh->source, "give one of blocks, a domain or a mesh, not several");
    for (const MeshMaterialSpec& m : spec_.mesh->materials) {
      if (!block_material_index_.count(m.material))
        fail(m.source,
             "unknown material " + quoted(m.material) + " for physical surface " + quoted(m.group));
    }
  }

  // The joint material of cuts through intact rock in a generated case (the domain's `intact`)
  // and between the cells of a mesh (`mesh.interfaces`): the one named, or if none, a continuum
  // (penalty) material added for it.
  int intact_material(const std::string& name, const SourceRef& source) {
    if (!name.empty())
      return joint_material(name, source);
    if (intact_ < 0) {
      JointMaterial j;
      j.name = "intact rock (continuum)";
      j.kind = JointMaterial::Kind::continuum;
      j.penalty_factor = model_.settings.penalty_factor;
      j.integration = Integration::gauss;
      j.source = source;
      intact_ = static_cast<int>(model_.joint_materials.size());
      model_.joint_materials.push_back(j);
    }
    return intact_;
  }

  int joint_material(const std::string& name, const SourceRef& ref) const {
    auto it = joint_material_index_.find(name);
    if (it == joint_material_index_.end())
      fail(ref, "unknown joint material " + quoted(name));
    return it->second;
  }

  void add_blocks() {
    const std::vector<BlockSpec>& blocks = generated_   ? generated_->blocks
                                           : spec_.mesh ? spec_.mesh->cells
                                                        : spec_.blocks;
    if (blocks.empty())
      fail({0, "blocks"}, "the case has no blocks");
    const CaseLimits& limits = spec_.limits;
    if (static_cast<double>(blocks.size()) > limits.blocks) {
      fail(spec_.mesh ? spec_.mesh->source : SourceRef{0, "blocks"},
           limit_message(static_cast<double>(blocks.size()), limits.blocks, "blocks", "blocks",
                         "give fewer blocks"));
    }
    // Each block with a strength has `planes` yield conditions (a planes x 3 matrix per block).
    double planes = 0.0;
    const BlockMaterial* widest = nullptr;
    for (const BlockSpec& b : blocks) {
      const auto it = block_material_index_.find(b.material);
      if (it == block_material_index_.end())
        continue;  // reported below
      const BlockMaterial& m = model_.block_materials[static_cast<std::size_t>(it->second)];
      if (m.strength) {
        planes += m.strength->planes;
        if (!widest || m.strength->planes > widest->strength->planes)
          widest = &m;
      }
    }
    if (planes > limits.yield_planes) {
      fail({widest->source.line, widest->source.item + ".strength.planes"},
           limit_message(planes, limits.yield_planes, "yield_planes",
                         "block yield planes (planes x blocks)", "give fewer planes"));
    }
    BBox box;
    for (const BlockSpec& b : blocks) {
      for (const Vec2& v : b.polygon.vertices) {
        if (!std::isfinite(v.x()) || !std::isfinite(v.y()))
          fail(b.source, "a vertex is not a finite number (NaN or infinity)");
        box.add(v);
      }
    }
    model_.tolerance = model_tolerance(box);
    for (const BlockSpec& b : blocks) {
      auto it = block_material_index_.find(b.material);
      if (it == block_material_index_.end())
        fail(b.source, "unknown material " + quoted(b.material));
      const PolygonCheck check = check_convex_polygon(b.polygon, model_.tolerance);
      if (check.defect != PolygonDefect::none)
        fail(b.source, describe(check));
      model_.blocks.push_back(
          {b.polygon, centroid(b.polygon), signed_area(b.polygon), it->second, b.source});
    }
    polygons_.reserve(model_.blocks.size());
    for (const Block& b : model_.blocks)
      polygons_.push_back(b.polygon);
    const auto overlaps = find_overlaps(polygons_, model_.tolerance);
    if (!overlaps.empty()) {
      const auto [i, j] = overlaps.front();
      fail(model_.blocks[j].source,
           "overlaps " + describe_block(i) + " (blocks may touch along edges but not overlap)");
    }
  }

  std::string describe_block(int k) const {
    const SourceRef& s = model_.blocks[k].source;
    std::string d = s.item.empty() ? "block " + std::to_string(k) : s.item;
    if (s.line > 0)
      d += " (line " + std::to_string(s.line) + ")";
    return d;
  }

  // Springs of an interface between blocks i and j (j may be kGround) of joint material m,
  // or a rigid penalty support when m < 0.
  SpringPair springs(int m, int i, int j) const {
    if (m >= 0 && model_.joint_materials[m].kind == JointMaterial::Kind::springs)
      return {model_.joint_materials[m].normal_stiffness,
              model_.joint_materials[m].shear_stiffness};
    // Penalty (eq. 15): k = p E / l, E the stiffer block, l = sqrt of the mean block area.
    const double p =
        m >= 0 ? model_.joint_materials[m].penalty_factor : model_.settings.penalty_factor;
    double e = model_.block_materials[model_.blocks[i].material].young;
    double area = model_.blocks[i].area;
    if (j != kGround) {
      e = std::max(e, model_.block_materials[model_.blocks[j].material].young);
      area = 0.5 * (area + model_.blocks[j].area);
    }
    const double k = p * e / std::sqrt(area);
    return {k, k};
  }

  // Throws when `more` interface segments would take the model past limits.interfaces.
  void check_interfaces(double more, const SourceRef& source, const std::string& what) const {
    const double total = static_cast<double>(model_.interfaces.size()) + more;
    if (total > spec_.limits.interfaces) {
      fail(source, limit_message(total, spec_.limits.interfaces, "interfaces",
                                 "interface segments (" + what + ")", "give fewer subdivisions"));
    }
  }

  void push_interface(Interface f, int subdivisions) {
    const Segment s = f.segment;
    for (int k = 0; k < subdivisions; ++k) {
      f.segment = {s.at(double(k) / subdivisions), s.at(double(k + 1) / subdivisions)};
      model_.interfaces.push_back(f);
    }
  }

  void add_interfaces() {
    shared_ = find_shared_edges(polygons_, model_.tolerance);
    std::vector<int> material(shared_.size(), -1);
    if (!spec_.default_joint.empty()) {
      const int m = joint_material(spec_.default_joint, {0, "joints.default"});
      std::fill(material.begin(), material.end(), m);
    }
    if (generated_) {  // the joint sets' materials, intact rock elsewhere; rules still override
      for (std::size_t k = 0; k < shared_.size(); ++k) {
        const std::string name = generated_->joint_between(shared_[k].i, shared_[k].j);
        material[k] = name.empty() ? intact_material(spec_.domain->intact, spec_.domain->source)
                                   : joint_material(name, spec_.domain->source);
      }
    }
    if (spec_.mesh && !shared_.empty())  // every cell-to-cell interface; rules still override
      std::fill(material.begin(), material.end(),
                intact_material(spec_.mesh->interfaces, spec_.mesh->source));
    for (const JointRule& rule : spec_.joint_rules) {
      const int m = joint_material(rule.material, rule.source);
      bool any = false;
      for (std::size_t k = 0; k < shared_.size(); ++k) {
        if (selects(rule.where, shared_[k].segment, model_.tolerance)) {
          material[k] = m;
          any = true;
        }
      }
      if (!any)
        fail(rule.source, "selects no interface between blocks");
    }
    double segments = 0.0;
    int most = -1;  // the joint material with the most subdivisions
    for (std::size_t k = 0; k < shared_.size(); ++k) {
      if (material[k] < 0)
        continue;
      const int n = model_.joint_materials[static_cast<std::size_t>(material[k])].subdivisions;
      segments += n;
      if (most < 0 || n > model_.joint_materials[static_cast<std::size_t>(most)].subdivisions)
        most = material[k];
    }
    if (most >= 0) {
      const JointMaterial& jm = model_.joint_materials[static_cast<std::size_t>(most)];
      check_interfaces(segments, {jm.source.line, jm.source.item + ".subdivisions"},
                       "interfaces between blocks x subdivisions");
    }
    for (std::size_t k = 0; k < shared_.size(); ++k) {
      const SharedEdge& s = shared_[k];
      if (material[k] < 0) {
        const Vec2 mid = s.segment.midpoint();
        fail({0, "joints"},
             "the interface between " + describe_block(s.i) + " and " + describe_block(s.j) +
                 " at (" + std::to_string(mid.x()) + ", " + std::to_string(mid.y()) +
                 ") has no joint material: give a default or a rule that selects it");
      }
      const JointMaterial& jm = model_.joint_materials[material[k]];
      const SpringPair k_ns = springs(material[k], s.i, s.j);
      push_interface(
          {s.i, s.j, s.segment, s.normal, k_ns.normal, k_ns.shear, jm.integration, material[k], -1},
          jm.subdivisions);
    }
  }

  void add_supports() {
    model_.boundary = find_boundary_edges(polygons_, shared_, model_.tolerance);
    std::vector<int> supported_by(model_.boundary.size(), -1);
    for (std::size_t sup = 0; sup < spec_.supports.size(); ++sup) {
      const SupportSpec& s = spec_.supports[sup];
      const int m = s.joint_material ? joint_material(*s.joint_material, s.source) : -1;
      bool any = false;
      for (std::size_t e = 0; e < model_.boundary.size(); ++e) {
        const BoundaryEdge& edge = model_.boundary[e];
        if (!selects(s.where, edge.segment, model_.tolerance))
          continue;
        if (supported_by[e] >= 0)
          fail(s.source, "selects a boundary edge already held by " +
                             spec_.supports[supported_by[e]].source.item);
        supported_by[e] = static_cast<int>(sup);
        any = true;
        SpringPair k_ns = springs(m, edge.polygon, kGround);
        if (s.kind == SupportKind::roller)
          k_ns.shear = 0.0;
        const Integration rule =
            m >= 0 ? model_.joint_materials[m].integration : Integration::lobatto;
        const int subdivisions = m >= 0 ? model_.joint_materials[m].subdivisions : 1;
        check_interfaces(subdivisions, s.source, "supported edges x subdivisions");
        push_interface({edge.polygon, kGround, edge.segment, edge.outward_normal, k_ns.normal,
                        k_ns.shear, rule, m, static_cast<int>(sup)},
                       subdivisions);
      }
      if (!any)
        fail(s.source, "selects no boundary edge");
    }
  }

  // The block of every point of a load or monitor (the first in the blocks' order that holds
  // it), found at once by box intersection: a search of all blocks per point took 13.6 s for
  // 20 000 monitors on 40 000 blocks, and would for as many stages with a point load each.
  void locate_points() {
    std::vector<Vec2> points;
    const auto add = [&](const Vec2& p) {
      if (std::isfinite(p.x()) && std::isfinite(p.y()))
        points.push_back(p);
    };
    for (const PointLoadSpec& p : spec_.loads.points)
      add(p.point);
    for (const MonitorSpec& m : spec_.monitors)
      add(m.point);
    for (const StageSpec& st : spec_.stages) {
      for (const PointLoadSpec& p : st.loads.points)
        add(p.point);
    }
    const std::vector<int> blocks = first_containing(polygons_, points, model_.tolerance);
    for (std::size_t k = 0; k < points.size(); ++k)
      located_[{points[k].x(), points[k].y()}] = blocks[k];
  }

  int block_at(const Vec2& p, const SourceRef& ref, const std::string& what) const {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      fail(ref, what + " is not a finite point");
    const int b = located_.at({p.x(), p.y()});
    if (b < 0)
      fail(ref, what + " (" + std::to_string(p.x()) + ", " + std::to_string(p.y()) +
                    ") lies in no block");
    return b;
  }

  Loads resolve_loads(const LoadsSpec& l, const std::string& where) const {
    if (!std::isfinite(l.gravity.x()) || !std::isfinite(l.gravity.y()))
      fail({0, where + ".gravity"}, "gravity must be finite");
    Loads loads;
    loads.gravity = l.gravity;
    for (const PointLoadSpec& p : l.points) {
      if (!std::isfinite(p.force.x()) || !std::isfinite(p.force.y()))
        fail(p.source, "force must be finite");
      loads.points.push_back({block_at(p.point, p.source, "the point"), p.point, p.force});
    }
    for (const TractionSpec& t : l.tractions) {
      if (!std::isfinite(t.normal) || !std::isfinite(t.shear))
        fail(t.source, "traction must be finite");
      bool any = false;
      for (const BoundaryEdge& e : model_.boundary) {
        if (!selects(t.where, e.segment, model_.tolerance))
          continue;
        any = true;
        loads.tractions.push_back({e.polygon, e.segment, e.outward_normal, t.normal, t.shear});
      }
      if (!any)
        fail(t.source, "selects no boundary edge");
    }
    return loads;
  }

  void add_loads() {
    model_.loads = resolve_loads(spec_.loads, "loads");
    if (spec_.loads.water) {
      model_.loads.water = water_faces(model_, *spec_.loads.water);
      model_.loads.water_surface = spec_.loads.water->surface;
    }
  }

  /// A stage's water replaces the water in force: its loads hold the change.
  void add_stage_water(const StageSpec& st, Stage& stage,
                       std::vector<PressureFace>& in_force) const {
    if (!st.loads.water) {
      stage.loads.water_surface =
          model_.stages.empty() ? std::vector<Vec2>{} : model_.stages.back().loads.water_surface;
      return;
    }
    std::vector<PressureFace> faces = water_faces(model_, *st.loads.water);
    stage.loads.water = faces;
    for (PressureFace f : in_force) {
      f.pressure_a = -f.pressure_a;
      f.pressure_b = -f.pressure_b;
      stage.loads.water.push_back(f);
    }
    stage.loads.water_surface = st.loads.water->surface;
    in_force = std::move(faces);
  }

  void add_stages() {
    double increments = 0.0;
    std::vector<PressureFace> water_in_force;
    for (const StageSpec& st : spec_.stages) {
      increments += st.increments;
      if (increments > spec_.limits.increments) {
        fail({st.source.line, st.source.item + ".increments"},
             limit_message(increments, spec_.limits.increments, "increments",
                           "load increments (over all stages)", "give fewer increments"));
      }
      Stage stage;
      stage.name = st.name;
      stage.loads = resolve_loads(st.loads, st.source.item);
      stage.increments = st.increments;
      stage.source = st.source;
      if (st.increments < 1)
        fail(st.source, "increments must be at least 1");
      if (st.control) {
        const DisplacementControlSpec& c = *st.control;
        const auto named = monitor_index_.find(c.monitor);
        if (named == monitor_index_.end())
          fail(c.source, "unknown monitor '" + c.monitor + "'");
        const int monitor = named->second;
        if (!std::isfinite(c.displacement) || c.displacement == 0.0)
          fail(c.source, "the prescribed displacement must be a non-zero number");
        if (!std::isfinite(c.direction.norm()) || c.direction.norm() == 0.0)
          fail(c.source, "the direction must be a non-zero vector");
        stage.control = DisplacementControl{monitor, c.direction.normalized(), c.displacement};
      }
      add_stage_water(st, stage, water_in_force);
      model_.stages.push_back(std::move(stage));
    }
    resolve_stage_blocks(model_, spec_.stages);
    add_initial_stress();
    add_bolts(model_, spec_.bolts);
  }

  // The stress before the first stage: a nonlinear analysis only, its values finite.
  void add_initial_stress() {
    if (!spec_.initial_stress)
      return;
    const InitialStressSpec& s = *spec_.initial_stress;
    const std::string item = s.source.item.empty() ? "initial_stress" : s.source.item;
    if (spec_.stages.empty())
      fail({s.source.line, item},
           "is the stress before the first stage: give stages (an elastic analysis starts "
           "unstressed)");
    if (!s.uniform.allFinite())
      fail({s.source.line, item + ".stress"}, "must be finite");
    if (s.gravity) {
      const SourceRef ref{s.source.line, item + ".gravity"};
      if (!std::isfinite(s.gravity->ground_level))
        fail(ref, "ground_level must be finite");
      if (!finite_positive(s.gravity->unit_weight))
        fail(ref, "unit_weight must be positive");
      if (!finite_non_negative(s.gravity->k0))
        fail(ref, "k0 must be >= 0");
    }
    model_.initial_stress = s;
  }

  void add_monitors() {
    for (const MonitorSpec& m : spec_.monitors) {
      monitor_index_.emplace(m.name, static_cast<int>(model_.monitors.size()));
      model_.monitors.push_back(
          {m.name, block_at(m.point, m.source, "the monitor point"), m.point});
    }
  }

  const CaseSpec& spec_;
  Model model_;
  std::map<std::string, int> block_material_index_;
  std::map<std::string, int> joint_material_index_;
  std::vector<Polygon> polygons_;
  std::optional<GeneratedBlocks> generated_;
  int intact_ = -1;
  std::vector<SharedEdge> shared_;
  std::map<std::pair<double, double>, int> located_;  // point -> block (locate_points)
  std::map<std::string, int> monitor_index_;          // name -> index of Model::monitors
};

}  // namespace

Model build_model(const CaseSpec& spec) {
  return Builder(spec).build();
}

Model rebuild_model(const Model& built, const CaseSpec& spec) {
  return Builder(spec).rebuild(built);
}

int find_block_containing(const Model& model, const Vec2& p) {
  for (int k = 0; k < model.n_blocks(); ++k) {
    if (contains(model.blocks[k].polygon, p, model.tolerance))
      return k;
  }
  return -1;
}

}  // namespace bimrock
