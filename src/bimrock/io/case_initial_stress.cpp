/// @file The initial_stress section: the stress in the rock before the first stage, a uniform
/// part and a gravitational one.
#include <bimrock/io/case_sections.hpp>

#include <vector>

#include <fmt/core.h>

namespace bimrock::case_file {

namespace {

constexpr double kMaxK0 = 10.0;  // [-]: beyond any measured ratio of horizontal to vertical stress

/// ground_level [m], unit_weight [N/m^3] (bounded as a material's), k0 [-].
InitialStressSpec::Gravity read_gravity(const Value& v) {
  const Map m = open(v, "initial_stress.gravity");
  InitialStressSpec::Gravity g;
  g.ground_level = bounded(m.at("ground_level"), kMaxCoordinate, "m", "the model's extent");
  const Value unit_weight = m.at("unit_weight");
  g.unit_weight = bounded(unit_weight, 1e9, "N/m^3", "no material is that heavy");
  if (g.unit_weight <= 0.0)
    unit_weight.fail("must be positive");
  const Value k0 = m.at("k0");
  g.k0 = non_negative(k0);
  if (g.k0 > kMaxK0)
    k0.fail(
        fmt::format("must be at most {:g} (the ratio of horizontal to vertical stress)", kMaxK0));
  return g;
}

}  // namespace

/// stress: [sigma_xx, sigma_yy, tau_xy] [Pa], tension positive; gravity: the part growing with
/// depth below the ground level; allow_yield. At least one of stress and gravity.
InitialStressSpec read_initial_stress(const Value& v) {
  const Map m = open(v, "initial_stress");
  InitialStressSpec s;
  s.source = v.ref();
  const auto stress = m.find("stress");
  if (stress) {
    const std::vector<Value> c = stress->list();
    if (c.size() != 3)
      stress->fail("must be [sigma_xx, sigma_yy, tau_xy], three stresses in Pa (tension positive)");
    for (int k = 0; k < 3; ++k)
      s.uniform[k] = bounded(c[static_cast<std::size_t>(k)], kMaxForce, "Pa", kLarger);
  }
  const auto gravity = m.find("gravity");
  if (gravity)
    s.gravity = read_gravity(*gravity);
  if (!stress && !gravity)
    v.fail("give the stress, its gravitational part or both (stress, gravity)");
  s.allow_yield = m.boolean_or("allow_yield", false);
  return s;
}

}  // namespace bimrock::case_file
