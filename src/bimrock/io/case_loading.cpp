/// @file How a case is held and loaded: supports, loads (gravity, point loads, tractions, water)
/// and the load stages, each under load or displacement control, each excavating and installing
/// blocks.
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

/// from, to [m]; pressure: [p_from, p_to] [Pa], compression positive.
PressureLineSpec read_pressure_line(const Value& v) {
  const Map m = open(v, "loads.water.lines[]");
  PressureLineSpec l;
  l.from = location(m.at("from"));
  l.to = location(m.at("to"));
  if (l.from == l.to)
    m.at("to").fail("must differ from 'from'");
  const std::vector<Value> p = m.at("pressure").list();
  if (p.size() != 2)
    m.at("pressure").fail("must be [p_from, p_to], two pressures in Pa");
  const auto pressure = [](const Value& x) {
    const double value = bounded(x, kMaxForce, "Pa", kLarger);
    if (value < 0.0)
      x.fail("must not be negative (suction is not modelled)");
    return value;
  };
  l.pressure_from = pressure(p[0]);
  l.pressure_to = pressure(p[1]);
  l.source = v.ref();
  return l;
}

/// surface: [[x, y], ...] with x increasing [m]; unit_weight [N/m^3]; lines: pressure lines.
WaterSpec read_water(const Value& v) {
  const Map m = open(v, "loads.water");
  WaterSpec w;
  w.source = v.ref();
  if (const auto surface = m.find("surface")) {
    for (const Value& point : surface->list()) {
      const Vec2 p = location(point);
      if (!w.surface.empty() && p.x() <= w.surface.back().x())
        point.fail("the surface's x must increase from point to point");
      w.surface.push_back(p);
    }
    if (w.surface.size() < 2)
      surface->fail("needs at least two points");
  }
  if (const auto gamma = m.find("unit_weight")) {
    w.unit_weight = bounded(*gamma, 1e6, "N/m^3", "no fluid is that heavy");
    if (w.unit_weight <= 0.0)
      gamma->fail("must be positive");
  }
  if (const auto lines = m.find("lines"))
    w.lines = read_list(*lines, read_pressure_line);
  if (w.surface.empty() && w.lines.empty())
    v.fail("give a phreatic surface, pressure lines or both");
  return w;
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
  if (const auto w = m.find("water"))
    loads.water = read_water(*w);
  return loads;
}

namespace {

/// A load stage: its loads are added to the earlier stages' in `increments` steps, under load
/// control or with a monitor's displacement prescribed (control); it may excavate blocks and
/// install blocks, and release a fraction (0, 1] of the excavation forces not yet released.
/// @param excavated whether an earlier stage excavates; set when this one does.
StageSpec read_stage(const Value& v, bool& excavated) {
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
  if (const auto excavate = m.find("excavate"))
    st.excavate = read_block_selector(*excavate, "stages[].excavate");
  if (const auto install = m.find("install"))
    st.install = read_block_selector(*install, "stages[].install");
  excavated = excavated || st.excavate.has_value();
  if (const auto release = m.find("release")) {
    if (!excavated)
      release->fail(
          "no stage up to this one excavates a block: release applies to the forces "
          "of excavated blocks not yet released");
    st.release = release->number();
    if (st.release <= 0.0 || st.release > 1.0)
      release->fail(
          "must lie in (0, 1]: the fraction of the excavation forces not yet released "
          "that this stage releases");
  }
  return st;
}

}  // namespace

/// The stages, in order. `release` applies to the forces of blocks excavated by this stage or
/// an earlier one: before any excavation there is nothing to release.
std::vector<StageSpec> read_stages(const Value& v) {
  bool excavated = false;
  return read_list(v, [&](const Value& element) { return read_stage(element, excavated); });
}

}  // namespace bimrock::case_file
