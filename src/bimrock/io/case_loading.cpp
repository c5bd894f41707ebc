/// @file How a case is held and loaded: supports, loads (gravity, point loads, tractions) and
/// the load stages, each under load or displacement control.
#include <bimrock/io/case_sections.hpp>

#include <cmath>

namespace bimrock::case_file {

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

namespace {

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

}  // namespace

LoadsSpec read_loads(const Value& v) {
  const Map m = open(v, "loads");
  LoadsSpec loads;
  if (const auto g = m.find("gravity"))
    loads.gravity = bounded_vector(*g, 1e6, "g", kLarger);
  if (const auto p = m.find("points"))
    loads.points = read_list(*p, read_point_load);
  if (const auto t = m.find("tractions"))
    loads.tractions = read_list(*t, read_traction);
  if (const auto s = m.find("seismic")) {
    // Pseudo-static earthquake: kh times the weight along +x, kv times the weight downwards,
    // added to the body force of `gravity` (in units of the unit weight).
    const Map k = open(*s, "loads.seismic");
    const auto coefficient = [&](const char* key) {
      const auto x = k.find(key);
      return x ? bounded(*x, 2.0, "times the weight", "beyond any earthquake recorded") : 0.0;
    };
    loads.gravity += Vec2(coefficient("kh"), -coefficient("kv"));
  }
  return loads;
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

}  // namespace bimrock::case_file
