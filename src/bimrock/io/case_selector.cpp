/// @file Selectors: where a joint rule, support or traction applies (one of line, box,
/// orientation or group).
#include <bimrock/io/case_sections.hpp>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace bimrock::case_file {

namespace {

/// [[x1, y1], [x2, y2]]: two locations.
std::pair<Vec2, Vec2> two_locations(const Value& v, const char* what) {
  const std::vector<Value> p = v.list();
  if (p.size() != 2) {
    v.fail(std::string("must be ") + what + " (two points), not a list of " +
           std::to_string(p.size()));
  }
  return {location(p[0]), location(p[1])};
}

}  // namespace

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

}  // namespace bimrock::case_file
