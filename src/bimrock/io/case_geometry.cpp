/// @file The geometry of a case: blocks given by their vertices, or a domain cut into blocks by
/// joint sets and single joints; and the joints section, which assigns joint materials to the
/// interfaces by rules.
#include <bimrock/io/case_sections.hpp>

#include <optional>

namespace bimrock::case_file {

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

namespace {

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

}  // namespace

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

namespace {

JointRule read_joint_rule(const Value& v) {
  const Map m = open(v, "joints.rules[]");
  JointRule r;
  r.material = name(m.at("material"));
  r.where = read_selector(m, "line, box, orientation or group");
  r.source = v.ref();
  return r;
}

}  // namespace

/// joints: {default, rules}: the default material, then rules in order (later rules win).
void read_joints(const Value& v, CaseSpec& spec) {
  const Map m = open(v, "joints");
  if (const auto d = m.find("default"))
    spec.default_joint = name(*d);
  if (const auto rules = m.find("rules"))
    spec.joint_rules = read_list(*rules, read_joint_rule);
}

}  // namespace bimrock::case_file
