// The case-file reader: one small function per section, each knowing its keys (from the one
// table kKeys below), defaults, units and syntax checks. Everything that needs the whole model
// (convexity, overlaps, material names, positive stiffness) is left to build_model().
#include <bimrock/io/case_reader.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <utility>

#include <fmt/core.h>

#include <bimrock/io/gmsh_mesh.hpp>
#include <bimrock/io/yaml_value.hpp>
#include <bimrock/model/limits.hpp>

namespace bimrock {
namespace {

using yaml::Entry;
using yaml::Map;
using yaml::Value;

constexpr int kSchemaVersion = 1;

// Every key of schema 1: the reader validates each section against it and
// tests/io/case_file_docs_test.cpp checks docs/case-file.md documents each path.
constexpr std::array kKeys = {
    CaseKey{"", "schema", true},
    CaseKey{"", "title"},
    CaseKey{"", "analysis"},
    CaseKey{"", "materials", true},
    CaseKey{"", "joint_materials"},
    CaseKey{"", "blocks"},
    CaseKey{"", "domain"},
    CaseKey{"", "mesh"},
    CaseKey{"", "joints"},
    CaseKey{"", "supports"},
    CaseKey{"", "loads"},
    CaseKey{"", "monitors"},
    CaseKey{"", "output"},
    CaseKey{"", "stages"},
    CaseKey{"", "limits"},
    CaseKey{"analysis", "plane"},
    CaseKey{"analysis", "thickness"},
    CaseKey{"analysis", "penalty_factor"},
    CaseKey{"materials.<name>", "E", true},
    CaseKey{"materials.<name>", "nu", true},
    CaseKey{"materials.<name>", "unit_weight"},
    CaseKey{"materials.<name>", "strength"},
    CaseKey{"materials.<name>.strength", "criterion"},
    CaseKey{"materials.<name>.strength", "cohesion", true},
    CaseKey{"materials.<name>.strength", "friction"},
    CaseKey{"materials.<name>.strength", "dilation"},
    CaseKey{"materials.<name>.strength", "planes"},
    CaseKey{"joint_materials.<name>", "kn"},
    CaseKey{"joint_materials.<name>", "ks"},
    CaseKey{"joint_materials.<name>", "E"},
    CaseKey{"joint_materials.<name>", "nu"},
    CaseKey{"joint_materials.<name>", "h"},
    CaseKey{"joint_materials.<name>", "continuum"},
    CaseKey{"joint_materials.<name>", "penalty_factor"},
    CaseKey{"joint_materials.<name>", "integration"},
    CaseKey{"joint_materials.<name>", "subdivisions"},
    CaseKey{"joint_materials.<name>", "cohesion"},
    CaseKey{"joint_materials.<name>", "friction"},
    CaseKey{"joint_materials.<name>", "dilation"},
    CaseKey{"joint_materials.<name>", "tensile_strength"},
    CaseKey{"joint_materials.<name>", "residual_cohesion"},
    CaseKey{"joint_materials.<name>", "residual_friction"},
    CaseKey{"joint_materials.<name>", "residual_tensile_strength"},
    CaseKey{"joint_materials.<name>", "softening_slip"},
    CaseKey{"joint_materials.<name>", "softening_opening"},
    CaseKey{"blocks[]", "material", true},
    CaseKey{"blocks[]", "vertices", true},
    CaseKey{"domain", "outline", true},
    CaseKey{"domain", "holes"},
    CaseKey{"domain", "zones"},
    CaseKey{"domain", "material", true},
    CaseKey{"domain", "joint_sets"},
    CaseKey{"domain", "joints"},
    CaseKey{"domain", "intact"},
    CaseKey{"domain", "min_block_area"},
    CaseKey{"domain", "subdivision"},
    CaseKey{"domain.zones[]", "material", true},
    CaseKey{"domain.zones[]", "outline", true},
    CaseKey{"domain.joint_sets[]", "material", true},
    CaseKey{"domain.joint_sets[]", "dip", true},
    CaseKey{"domain.joint_sets[]", "spacing", true},
    CaseKey{"domain.joint_sets[]", "origin"},
    CaseKey{"domain.joint_sets[]", "trace_length"},
    CaseKey{"domain.joint_sets[]", "gap"},
    CaseKey{"domain.joint_sets[]", "staggered"},
    CaseKey{"domain.joint_sets[]", "spacing_variation"},
    CaseKey{"domain.joint_sets[]", "dip_variation"},
    CaseKey{"domain.joint_sets[]", "seed"},
    CaseKey{"domain.joint_sets[].<variation>", "distribution", true},
    CaseKey{"domain.joint_sets[].<variation>", "amount", true},
    CaseKey{"domain.joints[]", "material", true},
    CaseKey{"domain.joints[]", "from", true},
    CaseKey{"domain.joints[]", "to", true},
    CaseKey{"domain.subdivision", "size", true},
    CaseKey{"domain.subdivision", "pattern"},
    CaseKey{"domain.subdivision", "jitter"},
    CaseKey{"domain.subdivision", "seed"},
    CaseKey{"mesh", "file", true},
    CaseKey{"mesh", "materials", true},
    CaseKey{"mesh", "interfaces"},
    CaseKey{"joints", "default"},
    CaseKey{"joints", "rules"},
    CaseKey{"joints.rules[]", "material", true},
    CaseKey{"joints.rules[]", "line"},
    CaseKey{"joints.rules[]", "box"},
    CaseKey{"joints.rules[]", "orientation"},
    CaseKey{"joints.rules[]", "group"},
    CaseKey{"joints.rules[]", "tolerance"},
    CaseKey{"supports[]", "line"},
    CaseKey{"supports[]", "box"},
    CaseKey{"supports[]", "group"},
    CaseKey{"supports[]", "type"},
    CaseKey{"supports[]", "joint"},
    CaseKey{"loads", "gravity"},
    CaseKey{"loads", "points"},
    CaseKey{"loads", "tractions"},
    CaseKey{"loads.points[]", "at", true},
    CaseKey{"loads.points[]", "force", true},
    CaseKey{"loads.tractions[]", "line"},
    CaseKey{"loads.tractions[]", "box"},
    CaseKey{"loads.tractions[]", "group"},
    CaseKey{"loads.tractions[]", "normal", true},
    CaseKey{"loads.tractions[]", "shear"},
    CaseKey{"monitors[]", "name", true},
    CaseKey{"monitors[]", "at", true},
    CaseKey{"output", "vtk"},
    CaseKey{"output", "vtk_every"},
    CaseKey{"output", "csv"},
    CaseKey{"stages[]", "name", true},
    CaseKey{"stages[]", "increments"},
    CaseKey{"stages[]", "loads"},
    CaseKey{"stages[]", "control"},
    CaseKey{"stages[].control", "monitor", true},
    CaseKey{"stages[].control", "direction", true},
    CaseKey{"stages[].control", "displacement", true},
    CaseKey{"limits", "blocks"},
    CaseKey{"limits", "joint_traces"},
    CaseKey{"limits", "interfaces"},
    CaseKey{"limits", "yield_planes"},
    CaseKey{"limits", "increments"},
    CaseKey{"limits", "output_mb"},
};

std::vector<std::string_view> keys_of(std::string_view section) {
  std::vector<std::string_view> keys;
  for (const CaseKey& k : kKeys) {
    if (k.section == section)
      keys.push_back(k.key);
  }
  return keys;
}

/// Throws for the first required key of `section` that `m` lacks.
void require_keys(const Map& m, std::string_view section) {
  for (const CaseKey& k : kKeys) {
    if (k.section == section && k.required)
      static_cast<void>(m.at(k.key));
  }
}

/// The map `v` of a section: unknown and repeated keys rejected, required keys present.
Map open(const Value& v, std::string_view section) {
  Map m(v, keys_of(section));
  require_keys(m, section);
  return m;
}

// ---- Small typed values ------------------------------------------------------------------------

double positive(const Value& v) {
  const double d = v.number();
  if (d <= 0.0)
    v.fail("must be positive");
  return d;
}

/// A point [x, y] that is a position in the model [m]: each coordinate within kMaxCoordinate.
Vec2 location(const Value& v) {
  const Vec2 p = v.point();
  if (std::abs(p.x()) > kMaxCoordinate || std::abs(p.y()) > kMaxCoordinate) {
    v.fail(fmt::format("coordinates must lie within +-{:g} m, not [{:g}, {:g}]", kMaxCoordinate,
                       p.x(), p.y()));
  }
  return p;
}

/// A number whose magnitude is at most `max` (in `unit`): stiffnesses and loads far beyond any
/// rock or structure overflow the stiffness matrix or the solution, so they are refused.
double bounded(const Value& v, double max, const char* unit, const char* why) {
  const double d = v.number();
  if (std::abs(d) > max)
    v.fail(fmt::format("must be at most {:g} {} in magnitude ({})", max, unit, why));
  return d;
}

/// A point or vector [x, y] each of whose components is bounded(max).
Vec2 bounded_vector(const Value& v, double max, const char* unit, const char* why) {
  const Vec2 p = v.point();
  if (std::abs(p.x()) > max || std::abs(p.y()) > max) {
    v.fail(fmt::format("each component must be at most {:g} {} in magnitude ({})", max, unit, why));
  }
  return p;
}

constexpr double kMaxModulus = 1e15;    // [Pa]: 1000 times diamond's
constexpr double kMaxStiffness = 1e20;  // [Pa/m]: kn of a 1e15 Pa layer 10 um thick
constexpr double kMaxForce = 1e15;      // [N], and [Pa] for tractions
constexpr const char* kStiffer = "no rock or joint is stiffer; larger values overflow";
constexpr const char* kLarger = "larger loads overflow the displacements";

/// One of a fixed set of names, e.g. plane: strain | stress.
template <class E>
E choice(const Value& v, std::initializer_list<std::pair<std::string_view, E>> options) {
  const std::string s = v.text();
  std::string names;
  for (const auto& [name, value] : options) {
    if (s == name)
      return value;
    if (!names.empty())
      names.append(", ");
    names.append(name);
  }
  v.fail("unknown value '" + s + "' (allowed: " + names + ")");
}

/// A non-empty name (material, monitor).
std::string name(const Value& v) {
  std::string s = v.text();
  if (s.empty())
    v.fail("must not be empty");
  return s;
}

/// [[x1, y1], [x2, y2]]: two locations.
std::pair<Vec2, Vec2> two_locations(const Value& v, const char* what) {
  const std::vector<Value> p = v.list();
  if (p.size() != 2) {
    v.fail(std::string("must be ") + what + " (two points), not a list of " +
           std::to_string(p.size()));
  }
  return {location(p[0]), location(p[1])};
}

template <class Read>
auto read_list(const Value& v, Read read) {
  std::vector<decltype(read(v))> out;
  for (const Value& element : v.list())
    out.push_back(read(element));
  return out;
}

// ---- Selectors ----------------------------------------------------------------------------------

/// Where a rule, support or traction applies: exactly one of line / box / orientation / group
/// (the section's key table says which of them it accepts). A group selector gets its segments
/// once the mesh is read (resolve_groups).
/// @param kinds the accepted keys as a phrase for the message, e.g. "line, box or group".
Selector read_selector(const Map& m, const char* kinds) {
  const std::optional<Value> line = m.find("line");
  const std::optional<Value> box = m.find("box");
  const std::optional<Value> orientation = m.find("orientation");
  const std::optional<Value> group = m.find("group");
  const int given = int(line.has_value()) + int(box.has_value()) + int(orientation.has_value()) +
                    int(group.has_value());
  if (given == 0)
    m.self().fail(std::string("say where it applies: give one of ") + kinds);
  if (given > 1)
    m.self().fail(std::string("give only one of ") + kinds);

  Selector s;
  if (line) {
    const auto [a, b] = two_locations(*line, "a segment [[x1, y1], [x2, y2]]");
    s.kind = Selector::Kind::line;
    s.line = {a, b};
    s.source = line->ref();
  } else if (box) {
    const auto [lo, hi] = two_locations(*box, "a box [[xmin, ymin], [xmax, ymax]]");
    if (lo.x() > hi.x() || lo.y() > hi.y())
      box->fail("the first corner must be the lower-left one: [[xmin, ymin], [xmax, ymax]]");
    s.kind = Selector::Kind::box;
    s.box = BBox{lo, hi};
    s.source = box->ref();
  } else if (group) {
    s.kind = Selector::Kind::group;
    s.group = group->text();
    if (s.group.empty())
      group->fail("must name a physical curve of the mesh");
    s.source = group->ref();
  } else {
    s.kind = Selector::Kind::orientation;
    s.angle_deg = orientation->number();
    s.source = orientation->ref();
  }
  if (const std::optional<Value> tol = m.find("tolerance")) {
    if (!orientation)
      tol->fail("applies only to an orientation selector");
    s.angle_tolerance_deg = tol->number();
    if (s.angle_tolerance_deg < 0.0)
      tol->fail("must be >= 0 (degrees)");
  }
  return s;
}

// ---- Sections -----------------------------------------------------------------------------------

/// `schema: 1` must come first, so that a file that is not a case file (or a later schema) is
/// recognised before anything else is said about it.
void check_schema(const Value& root) {
  const std::vector<Entry> entries = root.entries();
  if (entries.empty())
    root.fail("the case file is empty: it must start with 'schema: 1'");
  const Entry& first = entries.front();
  if (first.key != "schema") {
    for (const Entry& e : entries) {
      if (e.key == "schema")
        e.value.fail("must be the first key of the file");
    }
    throw InputError(std::string(root.file()), first.value.line(), "schema",
                     "missing: a case file starts with 'schema: 1' (found '" + first.key + "')");
  }
  const int version = first.value.integer();
  if (version != kSchemaVersion) {
    first.value.fail("unsupported version " + std::to_string(version) +
                     ": this bimrock reads schema " + std::to_string(kSchemaVersion));
  }
}

AnalysisSettings read_analysis(const Value& v) {
  const Map m = open(v, "analysis");
  AnalysisSettings s;
  if (const auto plane = m.find("plane"))
    s.plane =
        choice<PlaneMode>(*plane, {{"strain", PlaneMode::strain}, {"stress", PlaneMode::stress}});
  if (const auto t = m.find("thickness"))
    s.thickness = positive(*t);
  if (const auto p = m.find("penalty_factor"))
    s.penalty_factor = positive(*p);
  return s;
}

/// A map name -> item (materials, joint_materials); names must not be empty.
template <class Read>
auto read_named(const Value& v, Read read) {
  std::vector<decltype(read(v.entries().front()))> out;
  for (const Entry& e : v.entries()) {
    if (e.key.empty())
      e.value.fail("a name must not be empty");
    out.push_back(read(e));
  }
  return out;
}

/// An angle in degrees, 0 <= angle < 90.
double angle_deg(const Value& v) {
  const double a = v.number();
  if (a < 0.0 || a >= 90.0)
    v.fail("must be an angle in degrees, 0 <= angle < 90");
  return a;
}

double non_negative(const Value& v) {
  const double d = v.number();
  if (d < 0.0)
    v.fail("must be >= 0");
  return d;
}

constexpr double kDegree = 3.14159265358979323846 / 180.0;

/// Mohr-Coulomb or Tresca on the block's mean stress: cohesion [Pa], friction and dilation
/// [deg], planes of the linearized criterion (docs/formulation.md).
BlockStrength read_block_strength(const Value& v) {
  const Map m = open(v, "materials.<name>.strength");
  BlockStrength s;
  if (const auto c = m.find("criterion"))
    s.criterion = choice<BlockStrength::Criterion>(
        *c, {{"mohr_coulomb", BlockStrength::Criterion::mohr_coulomb},
             {"tresca", BlockStrength::Criterion::tresca}});
  s.cohesion = non_negative(m.at("cohesion"));
  const auto friction = m.find("friction");
  const auto dilation = m.find("dilation");
  if (s.criterion == BlockStrength::Criterion::tresca && (friction || dilation))
    (friction ? *friction : *dilation).fail("Tresca has no friction or dilation angle");
  if (friction)
    s.friction = std::sin(angle_deg(*friction) * kDegree);
  s.dilation = dilation ? std::sin(angle_deg(*dilation) * kDegree) : s.friction;
  if (const auto planes = m.find("planes")) {
    s.planes = planes->integer();
    if (s.planes < 4)
      planes->fail("must be at least 4");
  }
  return s;
}

/// A strength parameter with optional linear softening to `residual` over `distance`.
Softening softening(const Map& m, const char* peak_key, const char* residual_key,
                    const char* distance_key, double scale, bool angle) {
  const auto read = [&](const Value& v) {
    return angle ? std::tan(angle_deg(v) * kDegree) : non_negative(v) * scale;
  };
  const auto peak = m.find(peak_key);
  Softening s = Softening::constant(peak ? read(*peak) : 0.0);
  if (const auto residual = m.find(residual_key)) {
    s.residual = read(*residual);
    const auto distance = m.find(distance_key);
    if (!distance)
      residual->fail(std::string("needs ") + distance_key + " (how far it takes to soften)");
    s.distance = non_negative(*distance);
  }
  return s;
}

/// Mohr-Coulomb with tension cut-off of a joint (docs/formulation.md): cohesion [Pa], friction
/// and dilation [deg], tensile strength [Pa], with optional linear softening.
std::optional<JointStrength> read_joint_strength(const Map& m) {
  const bool any = m.has("cohesion") || m.has("friction") || m.has("tensile_strength") ||
                   m.has("dilation") || m.has("residual_cohesion") || m.has("residual_friction") ||
                   m.has("residual_tensile_strength");
  if (!any) {
    for (const char* k : {"softening_slip", "softening_opening"})
      if (const auto v = m.find(k))
        v->fail("applies only to a joint with a strength (cohesion, friction, tensile_strength)");
    return std::nullopt;
  }
  JointStrength j;
  j.cohesion = softening(m, "cohesion", "residual_cohesion", "softening_slip", 1.0, false);
  j.friction = softening(m, "friction", "residual_friction", "softening_slip", 1.0, true);
  j.tensile = softening(m, "tensile_strength", "residual_tensile_strength", "softening_opening",
                        1.0, false);
  if (const auto d = m.find("dilation"))
    j.dilation = std::tan(angle_deg(*d) * kDegree);
  return j;
}

/// E [Pa], nu [-], unit_weight [N/m^3] (default 0). Ranges are build_model's to check.
BlockMaterial read_block_material(const Entry& e) {
  const Map m = open(e.value, "materials.<name>");
  BlockMaterial b;
  b.name = e.key;
  b.young = bounded(m.at("E"), kMaxModulus, "Pa", kStiffer);
  b.poisson = m.at("nu").number();
  if (const auto w = m.find("unit_weight"))
    b.unit_weight = bounded(*w, 1e9, "N/m^3", "no material is that heavy");
  b.source = e.value.ref();
  if (const auto strength = m.find("strength"))
    b.strength = read_block_strength(*strength);
  return b;
}

/// Three alternative forms: springs kn, ks [Pa/m]; a layer E [Pa], nu, h [m] turned into
/// springs by eq. 7 in the analysis' plane mode; or a continuum interface by penalty (eq. 15).
JointMaterial read_joint_material(const Entry& e, const AnalysisSettings& settings) {
  const Map m = open(e.value, "joint_materials.<name>");
  JointMaterial j;
  j.name = e.key;
  j.source = e.value.ref();

  const bool springs = m.has("kn") || m.has("ks");
  const bool layer = m.has("E") || m.has("nu") || m.has("h");
  const std::optional<Value> continuum_key = m.find("continuum");
  const bool continuum = continuum_key && continuum_key->boolean();
  const int forms = int(springs) + int(layer) + int(continuum);
  if (forms != 1) {
    e.value.fail(std::string(forms == 0 ? "say what it is: " : "mixes forms: ") +
                 "give kn and ks (springs), or E, nu and h (a layer), or continuum: true");
  }
  if (!continuum) {
    if (const auto p = m.find("penalty_factor"))
      p->fail("applies only to continuum: true");
  }

  if (springs) {
    j.normal_stiffness = bounded(m.at("kn"), kMaxStiffness, "Pa/m", kStiffer);
    j.shear_stiffness = bounded(m.at("ks"), kMaxStiffness, "Pa/m", kStiffer);
  } else if (layer) {
    // Checked here, not in build_model: the springs derived from a bad layer would hide the cause.
    const double young = positive(m.at("E"));
    static_cast<void>(bounded(m.at("E"), kMaxModulus, "Pa", kStiffer));
    const Value nu = m.at("nu");
    const double poisson = nu.number();
    if (poisson <= -1.0 || poisson >= 0.5)
      nu.fail("must lie in (-1, 0.5)");
    const double h = positive(m.at("h"));
    if (h < 1e-6)
      m.at("h").fail("must be at least 1e-6 m (a thinner layer's springs overflow)");
    const SpringPair k = layer_stiffness(young, poisson, h, settings.plane);
    j.normal_stiffness = k.normal;
    j.shear_stiffness = k.shear;
  } else {
    j.kind = JointMaterial::Kind::continuum;
    const auto p = m.find("penalty_factor");
    j.penalty_factor = p ? positive(*p) : settings.penalty_factor;
  }

  // End-point springs let blocks topple (docs/formulation.md); a continuum never opens, so it
  // takes the exact elastic stiffness of 2-point Gauss.
  j.integration = continuum ? Integration::gauss : Integration::lobatto;
  if (const auto rule = m.find("integration")) {
    j.integration = choice<Integration>(
        *rule, {{"lobatto", Integration::lobatto}, {"gauss", Integration::gauss}});
  }
  if (const auto n = m.find("subdivisions")) {
    j.subdivisions = n->integer();
    if (j.subdivisions < 1)
      n->fail("must be at least 1");
  }
  j.strength = read_joint_strength(m);
  if (continuum && j.strength)
    e.value.fail("a continuum interface has no strength: give kn and ks (or E, nu, h) instead");
  return j;
}

/// material, vertices [[x, y], ...] [m] counter-clockwise. The shape is build_model's to check.
BlockSpec read_block(const Value& v) {
  const Map m = open(v, "blocks[]");
  BlockSpec b;
  b.material = name(m.at("material"));
  for (const Value& p : m.at("vertices").list())
    b.polygon.vertices.push_back(location(p));
  b.source = v.ref();
  return b;
}

// ---- Domain (generated blocks)
// -------------------------------------------------------------------

/// [[x, y], ...]: a polygon's vertices (its shape is checked when the blocks are cut).
Polygon read_polygon(const Value& v) {
  Polygon p;
  for (const Value& point : v.list())
    p.vertices.push_back(location(point));
  return p;
}

Variation read_variation(const Value& v) {
  const Map m = open(v, "domain.joint_sets[].<variation>");
  Variation r;
  r.distribution = choice<Distribution>(
      m.at("distribution"), {{"uniform", Distribution::uniform}, {"normal", Distribution::normal}});
  r.amount = m.at("amount").number();
  if (r.amount < 0.0)
    m.at("amount").fail("must be >= 0");
  return r;
}

/// A whole number >= 0 for a random seed.
std::uint64_t seed(const Value& v) {
  const int s = v.integer();
  if (s < 0)
    v.fail("must be a whole number >= 0");
  return static_cast<std::uint64_t>(s);
}

JointSet read_joint_set(const Value& v) {
  const Map m = open(v, "domain.joint_sets[]");
  JointSet j;
  j.material = name(m.at("material"));
  j.dip_deg = m.at("dip").number();
  j.spacing = positive(m.at("spacing"));
  if (const auto o = m.find("origin"))
    j.origin = location(*o);
  if (const auto l = m.find("trace_length"))
    j.trace_length = positive(*l);
  j.gap = m.number_or("gap", 0.0);
  if (j.gap < 0.0)
    m.at("gap").fail("must be >= 0");
  j.staggered = m.boolean_or("staggered", false);
  if (const auto sv = m.find("spacing_variation"))
    j.spacing_variation = read_variation(*sv);
  if (const auto dv = m.find("dip_variation"))
    j.dip_variation = read_variation(*dv);
  if (const auto s = m.find("seed"))
    j.seed = seed(*s);
  return j;
}

Joint read_single_joint(const Value& v) {
  const Map m = open(v, "domain.joints[]");
  return {name(m.at("material")), Segment{location(m.at("from")), location(m.at("to"))}};
}

/// domain: the outline, holes and zones to cut, the joint sets and joints that cut it.
DomainSpec read_domain(const Value& v) {
  const Map m = open(v, "domain");
  DomainSpec d;
  d.source = v.ref();
  d.lines["domain"] = v.line();
  auto remember = [&](const Value& item) { d.lines[item.item()] = item.line(); };
  const Value outline = m.at("outline");
  remember(outline);
  d.domain.outline = read_polygon(outline);
  d.material = name(m.at("material"));
  if (const auto holes = m.find("holes")) {
    for (const Value& h : holes->list()) {
      remember(h);
      d.domain.holes.push_back(read_polygon(h));
    }
  }
  if (const auto zones = m.find("zones")) {
    for (const Value& z : zones->list()) {
      remember(z);
      const Map zm = open(z, "domain.zones[]");
      d.domain.zones.push_back({name(zm.at("material")), read_polygon(zm.at("outline"))});
    }
  }
  if (const auto sets = m.find("joint_sets")) {
    for (const Value& s : sets->list()) {
      remember(s);
      d.joint_sets.push_back(read_joint_set(s));
    }
  }
  if (const auto joints = m.find("joints")) {
    for (const Value& j : joints->list()) {
      remember(j);
      d.joints.push_back(read_single_joint(j));
    }
  }
  d.intact = m.text_or("intact", "");
  if (d.intact == "continuum")
    d.intact.clear();
  if (const auto a = m.find("min_block_area")) {
    const double area = a->number();
    if (area < 0.0)
      a->fail("must be >= 0");
    d.min_block_area = area;
  }
  if (const auto sub = m.find("subdivision")) {
    remember(*sub);
    const Map sm = open(*sub, "domain.subdivision");
    VoronoiOptions o;
    o.target_size = positive(sm.at("size"));
    if (const auto p = sm.find("pattern")) {
      o.pattern = choice<SeedPattern>(
          *p, {{"jittered_grid", SeedPattern::jittered_grid}, {"random", SeedPattern::random}});
    }
    o.jitter = sm.number_or("jitter", o.jitter);
    if (o.jitter < 0.0 || o.jitter > 1.0)
      sm.at("jitter").fail("must lie in [0, 1]");
    if (const auto s = sm.find("seed"))
      o.seed = seed(*s);
    d.subdivision = o;
  }
  return d;
}

// ---- Mesh (imported blocks) ---------------------------------------------------------------------

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names)
    out += (out.empty() ? "'" : ", '") + n + "'";
  return out.empty() ? "none" : out;
}

std::string cell_item(const MeshCell& c) {
  return "element " + std::to_string(c.tag) + " (surface " + std::to_string(c.surface) + ")";
}

/// The material of each cell: the one its physical surface is mapped to in mesh.materials.
/// Every physical surface with cells must be mapped, every key must be a physical surface.
void map_materials(const Value& materials, const GmshMesh& mesh, MeshSpec& spec) {
  for (const MeshCell& c : mesh.cells) {
    if (c.groups.empty()) {
      const std::string surface = std::to_string(c.surface);
      throw InputError(mesh.file, c.line, cell_item(c),
                       "belongs to no physical surface, so it has no material: in gmsh, put "
                       "surface " +
                           surface + " in a physical group (`Physical Surface(\"rock\") = {" +
                           surface + "};`) and map the group in mesh.materials");
    }
  }
  const std::vector<std::string> surfaces = mesh.group_names(2);
  std::map<std::string, std::string> material_of;
  for (const Entry& e : materials.entries()) {
    if (!std::binary_search(surfaces.begin(), surfaces.end(), e.key)) {
      e.value.fail("'" + e.key + "' is not a physical surface of " + mesh.file +
                   " (its physical surfaces: " + quoted_list(surfaces) + ")");
    }
    material_of[e.key] = name(e.value);
    spec.materials.push_back({e.key, material_of[e.key], e.value.ref()});
  }
  std::set<std::string> unmapped;
  for (const MeshCell& c : mesh.cells) {
    for (const std::string& g : c.groups) {
      if (!material_of.count(g))
        unmapped.insert(g);
    }
  }
  if (!unmapped.empty()) {
    materials.fail("no material for physical surface" +
                   std::string(unmapped.size() > 1 ? "s " : " ") +
                   quoted_list({unmapped.begin(), unmapped.end()}) + " of " + mesh.file +
                   ": map each to a block material, e.g. {" + *unmapped.begin() + ": <material>}");
  }
  for (const MeshCell& c : mesh.cells) {
    std::string material;
    for (const std::string& g : c.groups) {
      const std::string& m = material_of.at(g);
      if (!material.empty() && m != material) {
        throw InputError(mesh.file, c.line, cell_item(c),
                         "lies in physical surfaces " + quoted_list(c.groups) +
                             " mapped to different materials: give each cell one material");
      }
      material = m;
    }
    spec.cells.push_back(
        {c.polygon,
         material,
         {0, "mesh " + cell_item(c) + " (" + mesh.file + ":" + std::to_string(c.line) + ")"}});
  }
}

/// mesh: {file, materials, interfaces}: the cells of a gmsh mesh as blocks (io/gmsh_mesh.hpp).
/// The mesh file is relative to the case file's folder.
MeshSpec read_mesh(const Value& v, GmshMesh& mesh) {
  const Map m = open(v, "mesh");
  MeshSpec spec;
  spec.source = v.ref();
  const Value file = m.at("file");
  std::filesystem::path path(name(file));
  if (path.is_relative())
    path = std::filesystem::path(std::string(v.file())).parent_path() / path;
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    file.fail("cannot open the mesh file " + path.string() + ": " +
              (std::filesystem::exists(path, ec) ? "not a file" : "no such file") +
              " (a relative path is taken from the case file's folder)");
  }
  mesh = read_gmsh_mesh(path.string());
  spec.file = mesh.file;
  if (mesh.cells.empty())
    file.fail(mesh.file + " has no triangles or quadrangles (was it meshed in 2D, `gmsh -2`?)");
  const Value materials = m.at("materials");
  if (materials.entries().empty())
    materials.fail("map at least one physical surface to a block material");
  map_materials(materials, mesh, spec);
  if (const auto i = m.find("interfaces")) {
    spec.interfaces = name(*i);
    if (spec.interfaces == "continuum")
      spec.interfaces.clear();
  }
  return spec;
}

/// Fills the segments of every group selector from the line elements of the mesh's physical
/// curve of that name. A group that is not a physical curve is named with the ones there are.
void resolve_groups(CaseSpec& s, const GmshMesh* mesh) {
  const auto resolve = [&](Selector& sel) {
    if (sel.kind != Selector::Kind::group)
      return;
    if (!mesh) {
      throw InputError(s.file, sel.source,
                       "a group selects the line elements of a mesh's physical curve: give a "
                       "mesh section, or select by line or box");
    }
    for (const MeshLine& l : mesh->lines) {
      if (std::find(l.groups.begin(), l.groups.end(), sel.group) != l.groups.end())
        sel.segments.push_back(l.segment);
    }
    if (!sel.segments.empty())
      return;
    const std::vector<std::string> curves = mesh->group_names(1);
    const std::vector<std::string> surfaces = mesh->group_names(2);
    std::string why = "unknown group '" + sel.group + "': not a physical curve of " + mesh->file;
    if (std::binary_search(curves.begin(), curves.end(), sel.group))
      why = "physical curve '" + sel.group + "' of " + mesh->file + " has no line elements";
    else if (std::binary_search(surfaces.begin(), surfaces.end(), sel.group))
      why = "'" + sel.group + "' is a physical surface of " + mesh->file +
            "; select edges by a physical curve";
    throw InputError(s.file, sel.source,
                     why + " (its physical curves: " + quoted_list(curves) + ")");
  };
  for (JointRule& r : s.joint_rules)
    resolve(r.where);
  for (SupportSpec& sup : s.supports)
    resolve(sup.where);
  for (TractionSpec& t : s.loads.tractions)
    resolve(t.where);
  for (StageSpec& st : s.stages) {
    for (TractionSpec& t : st.loads.tractions)
      resolve(t.where);
  }
}

JointRule read_joint_rule(const Value& v) {
  const Map m = open(v, "joints.rules[]");
  JointRule r;
  r.material = name(m.at("material"));
  r.where = read_selector(m, "line, box, orientation or group");
  r.source = v.ref();
  return r;
}

/// joints: {default, rules}: the default material, then rules in order (later rules win).
void read_joints(const Value& v, CaseSpec& spec) {
  const Map m = open(v, "joints");
  if (const auto d = m.find("default"))
    spec.default_joint = name(*d);
  if (const auto rules = m.find("rules"))
    spec.joint_rules = read_list(*rules, read_joint_rule);
}

SupportSpec read_support(const Value& v) {
  const Map m = open(v, "supports[]");
  SupportSpec s;
  s.where = read_selector(m, "line, box or group");
  if (const auto type = m.find("type"))
    s.kind = choice<SupportKind>(*type,
                                 {{"fixed", SupportKind::fixed}, {"roller", SupportKind::roller}});
  if (const auto joint = m.find("joint"))
    s.joint_material = name(*joint);
  s.source = v.ref();
  return s;
}

/// at [m], force [N] (over the thickness t).
PointLoadSpec read_point_load(const Value& v) {
  const Map m = open(v, "loads.points[]");
  return {location(m.at("at")), bounded_vector(m.at("force"), kMaxForce, "N", kLarger), v.ref()};
}

/// normal, shear [Pa]: tension positive along the outward normal, shear along s = (-n_y, n_x).
TractionSpec read_traction(const Value& v) {
  const Map m = open(v, "loads.tractions[]");
  TractionSpec t;
  t.where = read_selector(m, "line, box or group");
  t.normal = bounded(m.at("normal"), kMaxForce, "Pa", kLarger);
  if (const auto shear = m.find("shear"))
    t.shear = bounded(*shear, kMaxForce, "Pa", kLarger);
  t.source = v.ref();
  return t;
}

LoadsSpec read_loads(const Value& v) {
  const Map m = open(v, "loads");
  LoadsSpec loads;
  if (const auto g = m.find("gravity"))
    loads.gravity = bounded_vector(*g, 1e6, "g", kLarger);
  if (const auto p = m.find("points"))
    loads.points = read_list(*p, read_point_load);
  if (const auto t = m.find("tractions"))
    loads.tractions = read_list(*t, read_traction);
  return loads;
}

/// A name that becomes part of a file name (a monitor's plot_<name>.png): no folder separator,
/// no control character, not "." or "..", and short enough for a file name with its prefix and
/// suffix (most file systems allow 255 bytes).
std::string file_name_part(const Value& v) {
  std::string s = name(v);
  constexpr std::size_t kMaxBytes = 200;
  if (s.size() > kMaxBytes) {
    v.fail(fmt::format("is {} bytes long: a name is part of a file name, at most {} bytes",
                       s.size(), kMaxBytes));
  }
  for (const char c : s) {
    if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      v.fail("must not contain '/', '\\' or control characters: a name is part of a file name");
    }
  }
  if (s == "." || s == "..")
    v.fail("must not be '.' or '..': a name is part of a file name");
  return s;
}

std::vector<MonitorSpec> read_monitors(const Value& v) {
  std::vector<MonitorSpec> monitors;
  std::map<std::string, std::size_t> named;  // each name's monitor (not a search: 1e5 monitors)
  for (const Value& element : v.list()) {
    const Map m = open(element, "monitors[]");
    const Value n = m.at("name");
    MonitorSpec monitor{file_name_part(n), location(m.at("at")), element.ref()};
    // Monitors are looked up by name (results columns, displacement control): names are unique.
    if (const auto [other, fresh] = named.emplace(monitor.name, monitors.size()); !fresh) {
      const SourceRef& first = monitors[other->second].source;
      n.fail("monitor name '" + monitor.name + "' already used by " + first.item + " (line " +
             std::to_string(first.line) + ")");
    }
    monitors.push_back(std::move(monitor));
  }
  return monitors;
}

/// A load stage: its loads are added to the earlier stages' in `increments` steps, under load
/// control or with a monitor's displacement prescribed (control).
StageSpec read_stage(const Value& v) {
  const Map m = open(v, "stages[]");
  StageSpec st;
  st.name = name(m.at("name"));
  st.source = v.ref();
  if (const auto n = m.find("increments")) {
    st.increments = n->integer();
    if (st.increments < 1)
      n->fail("must be at least 1");
  }
  if (const auto loads = m.find("loads"))
    st.loads = read_loads(*loads);
  if (const auto control = m.find("control")) {
    const Map c = open(*control, "stages[].control");
    DisplacementControlSpec d;
    d.monitor = name(c.at("monitor"));
    d.direction = c.at("direction").point();
    if (!std::isfinite(d.direction.norm()))
      c.at("direction").fail("is too long: give a unit vector");
    if (d.direction.norm() == 0.0)
      c.at("direction").fail("must not be the zero vector");
    d.displacement = bounded(c.at("displacement"), kMaxCoordinate, "m", "the model's extent");
    if (d.displacement == 0.0)
      c.at("displacement").fail("must not be zero");
    d.source = control->ref();
    st.control = d;
  }
  return st;
}

/// limits: each a positive number (a count, or MB for output_mb).
CaseLimits read_limits(const Value& v) {
  const Map m = open(v, "limits");
  CaseLimits l;
  const std::pair<const char*, double*> fields[] = {
      {"blocks", &l.blocks},         {"joint_traces", &l.joint_traces},
      {"interfaces", &l.interfaces}, {"yield_planes", &l.yield_planes},
      {"increments", &l.increments}, {"output_mb", &l.output_mb}};
  for (const auto& [key, field] : fields) {
    if (const auto x = m.find(key)) {
      *field = positive(*x);
      l.lines[std::string("limits.") + key] = x->line();
    }
  }
  return l;
}

OutputOptions read_output(const Value& v) {
  const Map m = open(v, "output");
  OutputOptions o;
  o.vtk = m.boolean_or("vtk", o.vtk);
  if (const auto every = m.find("vtk_every")) {
    o.vtk_every = every->integer();
    if (o.vtk_every < 1)
      every->fail("must be at least 1");
  }
  o.csv = m.boolean_or("csv", o.csv);
  return o;
}

/// The whole document. Sections are read in dependency order (analysis before the joint
/// materials that need its plane mode); missing required sections are reported last, so that an
/// error inside a section that is there (with its line) comes first.
Case read_document(const YAML::Node& doc, const std::string& file) {
  if (!doc.IsMap()) {
    throw InputError(file, doc.Mark().is_null() ? 0 : doc.Mark().line + 1, "",
                     "a case file is a map of sections (schema, materials, blocks, ...)");
  }
  const Value root(doc, file, 0, "");
  check_schema(root);
  const Map m(root, keys_of(""));

  Case c;
  CaseSpec& s = c.spec;
  s.file = file;
  s.title = m.text_or("title", "");
  if (const auto v = m.find("analysis"))
    s.settings = read_analysis(*v);
  if (const auto v = m.find("materials")) {
    s.block_materials = read_named(*v, read_block_material);
    if (s.block_materials.empty())
      v->fail("give at least one material");
  }
  if (const auto v = m.find("joint_materials")) {
    s.joint_materials =
        read_named(*v, [&](const Entry& e) { return read_joint_material(e, s.settings); });
  }
  if (const auto v = m.find("blocks")) {
    s.blocks = read_list(*v, read_block);
    if (s.blocks.empty())
      v->fail("give at least one block");
  }
  if (const auto v = m.find("domain")) {
    if (m.has("blocks"))
      v->fail("give either blocks or a domain to cut them from, not both");
    s.domain = read_domain(*v);
  }
  std::optional<GmshMesh> mesh;
  if (const auto v = m.find("mesh")) {
    if (m.has("blocks") || m.has("domain"))
      v->fail("give one of blocks, a domain or a mesh, not several");
    s.mesh = read_mesh(*v, mesh.emplace());
  }
  if (const auto v = m.find("joints"))
    read_joints(*v, s);
  if (const auto v = m.find("supports"))
    s.supports = read_list(*v, read_support);
  if (const auto v = m.find("loads"))
    s.loads = read_loads(*v);
  if (const auto v = m.find("monitors"))
    s.monitors = read_monitors(*v);
  if (const auto v = m.find("output"))
    c.output = read_output(*v);
  if (const auto v = m.find("limits"))
    s.limits = read_limits(*v);
  if (const auto v = m.find("stages")) {
    if (const auto loads = m.find("loads"))
      loads->fail("give loads either here (an elastic analysis) or in stages, not both");
    s.stages = read_list(*v, read_stage);
    if (s.stages.empty())
      v->fail("give at least one stage");
  }
  resolve_groups(s, mesh ? &*mesh : nullptr);
  require_keys(m, "");
  if (!m.has("blocks") && !m.has("domain") && !m.has("mesh"))
    throw InputError(file, 0, "blocks",
                     "required key 'blocks' is missing (or give a domain to cut the blocks from, "
                     "or a mesh)");
  return c;
}

/// The 1-based line of the first line that is neither blank nor a comment (0: none).
int first_content_line(const std::string& text) {
  std::istringstream in(text);
  std::string l;
  for (int line = 1; std::getline(in, l); ++line) {
    const std::size_t first = l.find_first_not_of(" \t\r");
    if (first != std::string::npos && l[first] != '#')
      return line;
  }
  return 0;
}

/// The 1-based line where a second YAML document starts (0: there is one document at most): its
/// first content after a `---` marker that follows content or an end marker `...` (the marker's
/// line if nothing follows), or content after `...`. Document
/// markers are only markers at the start of a line, outside any scalar, so a line scan finds
/// them exactly.
int second_document_line(const std::string& text) {
  const auto marker = [](const std::string& l, const char* m) {
    return l.rfind(m, 0) == 0 && (l.size() == 3 || l[3] == ' ' || l[3] == '\t' || l[3] == '\r');
  };
  const auto has_content = [](const std::string& l, std::size_t from) {
    const std::size_t first = l.find_first_not_of(" \t\r", from);
    return first != std::string::npos && l[first] != '#';
  };
  std::istringstream in(text);
  std::string l;
  bool content = false;  // the first document has begun
  bool ended = false;    // ... and an end marker `...` closed it
  int second = 0;        // the line of a second `---`: the second document's content follows
  for (int line = 1; std::getline(in, l); ++line) {
    if (marker(l, "---")) {
      if (content || ended) {
        if (has_content(l, 3))
          return line;
        second = second > 0 ? second : line;
      }
      content = true;
    } else if (marker(l, "...")) {
      ended = content;
    } else if (has_content(l, 0)) {
      if (ended || second > 0)
        return line;    // the line of the second document's first content, as yaml-cpp marks it
      if (l[0] != '%')  // a directive (%YAML 1.2) before the document is not content
        content = true;
    }
  }
  return second;
}

/// Parses the text; a syntax error becomes an InputError at the line yaml-cpp reports.
/// Not YAML::LoadAll: in yaml-cpp 0.7 it loops without end, allocating, on some malformed input
/// (a file holding only `,`). Load reads the first document only; a second one is found by
/// second_document_line() and refused.
YAML::Node parse(const std::string& text, const std::string& file) {
  if (const int line = second_document_line(text)) {
    throw InputError(file, line, "", "more than one YAML document ('---'): give one case per file");
  }
  YAML::Node document;
  try {
    document = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "malformed YAML: " + e.msg);
  }
  if (!document.IsDefined() || document.IsNull()) {
    if (const int line = first_content_line(text)) {
      throw InputError(file, line, "",
                       "malformed YAML: no value could be read from this line (a case file is a "
                       "map of sections, starting with 'schema: 1')");
    }
    throw InputError(file, 0, "", "the case file is empty: it must start with 'schema: 1'");
  }
  return document;
}

}  // namespace

std::span<const CaseKey> case_file_keys() {
  return kKeys;
}

Case read_case_string(const std::string& text, const std::string& name) {
  return read_document(parse(text, name), name);
}

Case read_case_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec))
    throw InputError(path, 0, "", "cannot open the case file: no such file");
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, 0, "", "cannot open the case file: it is a folder");
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path, 0, "", "cannot open the case file (is it readable?)");
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad())
    throw InputError(path, 0, "", "cannot read the case file");
  return read_case_string(text.str(), path);
}

}  // namespace bimrock
