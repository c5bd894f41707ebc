/// @file Selectors: where a joint rule, support or traction applies (one of line, box,
/// orientation or group), and which blocks a stage excavates or installs (one of region, box,
/// material or blocks).
#include <bimrock/io/case_sections.hpp>

#include <optional>
#include <set>
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

/// [[xmin, ymin], [xmax, ymax]]: a box, its lower-left corner first.
BBox read_box(const Value& v) {
  const auto [lo, hi] = two_locations(v, "a box [[xmin, ymin], [xmax, ymax]]");
  if (lo.x() > hi.x() || lo.y() > hi.y())
    v.fail("the first corner must be the lower-left one: [[xmin, ymin], [xmax, ymax]]");
  return BBox{lo, hi};
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
    s.kind = Selector::Kind::box;
    s.box = read_box(*box);
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

/// The blocks a stage excavates or installs (`section`: "stages[].excavate" or
/// "stages[].install"): exactly one of region (a polygon [m]; its shape is build_model's to
/// check), box [m], material (a name) or blocks (indices >= 0, each once; build_model checks them
/// against the model).
BlockSelector read_block_selector(const Value& v, std::string_view section) {
  const Map m = open(v, section);
  const std::optional<Value> region = m.find("region");
  const std::optional<Value> box = m.find("box");
  const std::optional<Value> material = m.find("material");
  const std::optional<Value> blocks = m.find("blocks");
  const int given = int(region.has_value()) + int(box.has_value()) + int(material.has_value()) +
                    int(blocks.has_value());
  if (given == 0)
    v.fail("say which blocks: give one of region, box, material or blocks");
  if (given > 1)
    v.fail("give only one of region, box, material or blocks");

  BlockSelector s;
  if (region) {
    s.kind = BlockSelector::Kind::region;
    for (const Value& p : region->list())
      s.region.vertices.push_back(location(p));
    if (s.region.size() < 3)
      region->fail("a region is a polygon [[x, y], ...] of at least 3 points");
    s.source = region->ref();
  } else if (box) {
    s.kind = BlockSelector::Kind::box;
    s.box = read_box(*box);
    s.source = box->ref();
  } else if (material) {
    s.kind = BlockSelector::Kind::material;
    s.material = name(*material);
    s.source = material->ref();
  } else {
    s.kind = BlockSelector::Kind::list;
    std::set<int> seen;
    for (const Value& b : blocks->list()) {
      const int index = b.integer();
      if (index < 0)
        b.fail("must be a block index: a whole number >= 0 (blocks count from 0)");
      if (!seen.insert(index).second)
        b.fail("block " + std::to_string(index) + " is listed twice");
      s.blocks.push_back(index);
    }
    if (s.blocks.empty())
      blocks->fail("list at least one block index");
    s.source = blocks->ref();
  }
  return s;
}

}  // namespace bimrock::case_file
