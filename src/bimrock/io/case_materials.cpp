/// @file The materials and joint_materials sections: elastic constants, the strength of blocks
/// and joints, and its softening.
#include <bimrock/io/case_sections.hpp>

#include <cmath>
#include <optional>
#include <string>

namespace bimrock::case_file {

namespace {

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

}  // namespace

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

}  // namespace bimrock::case_file
