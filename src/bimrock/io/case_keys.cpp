/// @file The schema's key table: every key of a case file, section by section, and the checks
/// that open a section's map against it (unknown, repeated and missing keys).
#include <array>

#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/case_sections.hpp>

namespace bimrock {
namespace {

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
    CaseKey{"", "initial_stress"},
    CaseKey{"", "bolts"},
    CaseKey{"", "factor_of_safety"},
    CaseKey{"", "limits"},
    CaseKey{"analysis", "plane"},
    CaseKey{"analysis", "thickness"},
    CaseKey{"analysis", "penalty_factor"},
    CaseKey{"analysis", "bracket_tolerance"},
    CaseKey{"analysis", "max_bisections"},
    CaseKey{"analysis", "max_rounds"},
    CaseKey{"analysis", "yield_tolerance"},
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
    CaseKey{"loads", "seismic"},
    CaseKey{"loads.points[]", "at", true},
    CaseKey{"loads.points[]", "force", true},
    CaseKey{"loads.tractions[]", "line"},
    CaseKey{"loads.tractions[]", "box"},
    CaseKey{"loads.tractions[]", "group"},
    CaseKey{"loads.tractions[]", "normal", true},
    CaseKey{"loads.tractions[]", "shear"},
    CaseKey{"loads.seismic", "kh"},
    CaseKey{"loads.seismic", "kv"},
    CaseKey{"loads", "water"},
    CaseKey{"loads.water", "surface"},
    CaseKey{"loads.water", "unit_weight"},
    CaseKey{"loads.water", "lines"},
    CaseKey{"loads.water.lines[]", "from", true},
    CaseKey{"loads.water.lines[]", "to", true},
    CaseKey{"loads.water.lines[]", "pressure", true},
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
    CaseKey{"stages[]", "excavate"},
    CaseKey{"stages[]", "install"},
    CaseKey{"stages[]", "release"},
    CaseKey{"stages[].excavate", "region"},
    CaseKey{"stages[].excavate", "box"},
    CaseKey{"stages[].excavate", "material"},
    CaseKey{"stages[].excavate", "blocks"},
    CaseKey{"stages[].install", "region"},
    CaseKey{"stages[].install", "box"},
    CaseKey{"stages[].install", "material"},
    CaseKey{"stages[].install", "blocks"},
    CaseKey{"initial_stress", "stress"},
    CaseKey{"initial_stress", "gravity"},
    CaseKey{"initial_stress", "allow_yield"},
    CaseKey{"initial_stress.gravity", "ground_level", true},
    CaseKey{"initial_stress.gravity", "unit_weight", true},
    CaseKey{"initial_stress.gravity", "k0", true},
    CaseKey{"bolts[]", "name"},
    CaseKey{"bolts[]", "kind", true},
    CaseKey{"bolts[]", "from", true},
    CaseKey{"bolts[]", "to", true},
    CaseKey{"bolts[]", "axial_stiffness", true},
    CaseKey{"bolts[]", "capacity", true},
    CaseKey{"bolts[]", "pretension"},
    CaseKey{"bolts[]", "shear_stiffness"},
    CaseKey{"bolts[]", "shear_capacity"},
    CaseKey{"bolts[]", "spacing"},
    CaseKey{"bolts[]", "install"},
    CaseKey{"factor_of_safety", "materials"},
    CaseKey{"factor_of_safety", "tolerance"},
    CaseKey{"factor_of_safety", "step"},
    CaseKey{"factor_of_safety", "after_stage"},
    CaseKey{"factor_of_safety", "largest"},
    CaseKey{"limits", "blocks"},
    CaseKey{"limits", "joint_traces"},
    CaseKey{"limits", "interfaces"},
    CaseKey{"limits", "yield_planes"},
    CaseKey{"limits", "increments"},
    CaseKey{"limits", "output_mb"},
};

}  // namespace

std::span<const CaseKey> case_file_keys() {
  return kKeys;
}

namespace case_file {

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

}  // namespace case_file
}  // namespace bimrock
