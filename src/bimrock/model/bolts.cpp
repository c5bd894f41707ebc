#include <bimrock/model/bolts.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <string_view>

#include <bimrock/model/stage_blocks.hpp>

namespace bimrock {
namespace {

// The stretch t0 <= t <= t1 of a bolt's line p(t) = from + t (to - from), 0 <= t <= 1, that lies
// inside a block.
struct Stretch {
  int block = 0;
  double t0 = 0.0;
  double t1 = 0.0;
};

// The stretch of the segment from `from` along `d` (t in [0, 1]) inside the convex polygon;
// t0 > t1: none. An edge within tol of the whole segment does not clip it, so that a bolt along
// a joint lies in the blocks on both sides and the overlap is found.
Stretch clip(const Polygon& poly, const Vec2& from, const Vec2& d, double tol) {
  Stretch s{0, 0.0, 1.0};
  for (std::size_t k = 0; k < poly.size() && s.t0 <= s.t1; ++k) {
    const Vec2 n = outward_normal(poly, k);
    const double f0 = n.dot(from - poly.vertices[k]);  // > 0: outside this edge's line
    const double fd = n.dot(d);
    if (std::abs(f0) <= tol && std::abs(f0 + fd) <= tol)
      continue;
    if (fd == 0.0) {
      if (f0 > 0.0)
        return {0, 1.0, 0.0};
      continue;
    }
    const double t = -f0 / fd;
    if (fd > 0.0)
      s.t1 = std::min(s.t1, t);  // leaves through this edge
    else
      s.t0 = std::max(s.t0, t);  // enters through it
  }
  return s;
}

bool segment_meets_box(const Vec2& a, const Vec2& b, const BBox& box, double tol) {
  return std::max(a.x(), b.x()) >= box.lo.x() - tol && std::min(a.x(), b.x()) <= box.hi.x() + tol &&
         std::max(a.y(), b.y()) >= box.lo.y() - tol && std::min(a.y(), b.y()) <= box.hi.y() + tol;
}

std::string point(const Vec2& p) {
  std::ostringstream s;
  s << '(' << p.x() << ", " << p.y() << ')';
  return s.str();
}

std::string number(double x) {
  std::ostringstream s;
  s << x;
  return s.str();
}

class BoltBuilder {
 public:
  BoltBuilder(Model& model, const std::vector<BoltSpec>& bolts) : model_(model), bolts_(bolts) {
    boxes_.reserve(model.blocks.size());
    for (const Block& b : model.blocks)
      boxes_.push_back(bbox_of(b.polygon));
  }

  void resolve() {
    for (std::size_t k = 0; k < bolts_.size(); ++k) {
      Bolt bolt = checked(k);
      add_springs(k, bolt);
      model_.bolts.push_back(std::move(bolt));
    }
  }

 private:
  [[noreturn]] void fail(const SourceRef& ref, const std::string& message) const {
    throw InputError(model_.source_file, ref, message);
  }

  std::string item(std::size_t k) const {
    const BoltSpec& b = bolts_[k];
    return b.source.item.empty() ? "bolts[" + std::to_string(k) + "]" : b.source.item;
  }

  // The bolt's item, or that of one of its keys, at the key's line (the bolt's if not recorded).
  SourceRef where(std::size_t k, std::string_view key = {}) const {
    const BoltSpec& b = bolts_[k];
    const std::string name = key.empty() ? item(k) : item(k) + "." + std::string(key);
    const auto line = b.lines.find(name);
    return {line == b.lines.end() ? b.source.line : line->second, name};
  }

  // The spec's numbers in their ranges, its stage found by name.
  Bolt checked(std::size_t k) const {
    const BoltSpec& s = bolts_[k];
    if (model_.stages.empty())
      fail(where(k),
           "a bolt is installed at the start of a stage: give stages (an elastic analysis has no "
           "bolts)");
    const auto positive = [&](double x, std::string_view key, const char* what) {
      if (!std::isfinite(x) || x <= 0.0)
        fail(where(k, key),
             std::string("must be a positive number (") + what + "), not " + number(x));
    };
    positive(s.axial_stiffness, "axial_stiffness", "the bolt's axial stiffness, N/m");
    positive(s.capacity, "capacity", "the bolt's tensile capacity, N");
    if (s.kind == BoltSpec::Kind::grouted && s.pretension != 0.0)
      fail(where(k, "pretension"),
           "a grouted bolt is bonded along its length and cannot be pretensioned: leave "
           "pretension out, or make the bolt anchored");
    if (!std::isfinite(s.pretension) || s.pretension < 0.0 || s.pretension >= s.capacity)
      fail(where(k, "pretension"), "must lie in [0, capacity) = [0, " + number(s.capacity) +
                                       ") N (a bolt tensioned to its capacity has yielded), not " +
                                       number(s.pretension));
    if (!std::isfinite(s.shear_stiffness) || s.shear_stiffness < 0.0)
      fail(where(k, "shear_stiffness"),
           "must be a number >= 0 (the bolt's shear stiffness, N/m; 0 or left out: the bolt "
           "carries no shear), not " +
               number(s.shear_stiffness));
    if (s.shear_capacity) {
      if (s.shear_stiffness == 0.0)
        fail(where(k, "shear_capacity"),
             "is given without a shear stiffness: give shear_stiffness (N/m) too, or leave "
             "shear_capacity out");
      positive(*s.shear_capacity, "shear_capacity", "the bolt's shear capacity, N");
    }
    if (s.spacing)
      positive(*s.spacing, "spacing", "the out-of-plane spacing of the bolts, m");
    if (!s.from.allFinite())
      fail(where(k, "from"), "must be a finite point [x, y]");
    if (!s.to.allFinite())
      fail(where(k, "to"), "must be a finite point [x, y]");
    if ((s.to - s.from).norm() <= model_.tolerance)
      fail(where(k, "to"),
           "coincides with the head 'from': a bolt runs from its head to its far end, a "
           "distinct point");

    Bolt b;
    b.name = s.name.empty() ? "bolt " + std::to_string(k) : s.name;
    b.kind = s.kind;
    b.from = s.from;
    b.to = s.to;
    b.axial_stiffness = s.axial_stiffness;
    b.shear_stiffness = s.shear_stiffness;
    b.capacity = s.capacity;
    b.shear_capacity = s.shear_capacity;
    b.pretension = s.pretension;
    b.per_model = model_.settings.thickness / s.spacing.value_or(model_.settings.thickness);
    b.stage = stage(k);
    b.source = {s.source.line, item(k)};
    return b;
  }

  // The stage named by `install` (the first stage without it); the name must be one stage's.
  int stage(std::size_t k) const {
    const std::string& name = bolts_[k].install;
    if (name.empty())
      return 0;
    int found = -1;
    for (int n = 0; n < static_cast<int>(model_.stages.size()); ++n) {
      if (model_.stages[static_cast<std::size_t>(n)].name != name)
        continue;
      if (found >= 0)
        fail(where(k, "install"), "names two stages, " + stage_item(found) + " and " +
                                      stage_item(n) + " ('" + name +
                                      "'): give the stages distinct names");
      found = n;
    }
    if (found < 0)
      fail(where(k, "install"), "no stage is named '" + name +
                                    "': give the name of the stage at whose start the "
                                    "bolt is installed");
    return found;
  }

  std::string stage_item(int n) const {
    const SourceRef& s = model_.stages[static_cast<std::size_t>(n)].source;
    return s.item.empty() ? "stage " + std::to_string(n) : s.item;
  }

  // The stretches of the bolt's line inside the blocks present at its installation, in order
  // from its head; they must cover the line, one after another.
  std::vector<Stretch> stretches(std::size_t k, const Bolt& bolt) {
    const double tol = model_.tolerance;
    const Vec2 d = bolt.to - bolt.from;
    const double length = d.norm();
    const std::vector<char>& present = present_at(bolt.stage);
    std::vector<Stretch> inside;
    for (int b = 0; b < model_.n_blocks(); ++b) {
      const auto i = static_cast<std::size_t>(b);
      if (!present[i] || !segment_meets_box(bolt.from, bolt.to, boxes_[i], tol))
        continue;
      Stretch s = clip(model_.blocks[i].polygon, bolt.from, d, tol);
      s.block = b;
      if ((s.t1 - s.t0) * length > tol)
        inside.push_back(s);
    }
    std::sort(inside.begin(), inside.end(), [](const Stretch& x, const Stretch& y) {
      return x.t0 < y.t0 || (x.t0 == y.t0 && x.block < y.block);
    });
    const double t_tol = tol / length;
    const auto at = [&](double t) { return point(bolt.from + t * d); };
    if (inside.empty())
      leaves(k, bolt, 0.0, 1.0);
    if (inside.front().t0 > t_tol)
      leaves(k, bolt, 0.0, inside.front().t0);
    for (std::size_t n = 1; n < inside.size(); ++n) {
      const Stretch& before = inside[n - 1];
      const Stretch& after = inside[n];
      if (after.t0 > before.t1 + t_tol)
        leaves(k, bolt, before.t1, after.t0);
      if (after.t0 < before.t1 - t_tol)
        fail(where(k), "runs along a joint, between block " + std::to_string(before.block) +
                           " and block " + std::to_string(after.block) + " from " + at(after.t0) +
                           " to " + at(std::min(before.t1, after.t1)) +
                           ": a bolt crosses the joints it meets");
    }
    if (inside.back().t1 < 1.0 - t_tol)
      leaves(k, bolt, inside.back().t1, 1.0);
    if (inside.size() < 2)
      fail(where(k), "lies within block " + std::to_string(inside.front().block) +
                         ": it crosses no joint, so it would join the block to itself");
    return inside;
  }

  // The bolt's line leaves the rock between p(t0) and p(t1).
  [[noreturn]] void leaves(std::size_t k, const Bolt& bolt, double t0, double t1) const {
    const Vec2 d = bolt.to - bolt.from;
    fail(where(k), "leaves the blocks present at its installation (" + stage_item(bolt.stage) +
                       " '" + model_.stages[static_cast<std::size_t>(bolt.stage)].name +
                       "') between " + point(bolt.from + t0 * d) + " and " +
                       point(bolt.from + t1 * d) +
                       ": a bolt runs inside the rock from its head to its far end");
  }

  // The blocks present during a stage, found once for all the bolts it installs.
  const std::vector<char>& present_at(int stage) {
    auto [at, fresh] = present_.try_emplace(stage);
    if (fresh)
      at->second = blocks_present(model_, stage);
    return at->second;
  }

  // An anchored bolt: one spring, head to far end; a grouted one: one at each joint it crosses.
  void add_springs(std::size_t k, const Bolt& bolt) {
    const std::vector<Stretch> inside = stretches(k, bolt);
    const auto index = static_cast<int>(model_.bolts.size());
    const Vec2 axis = (bolt.to - bolt.from).normalized();
    if (bolt.kind == BoltSpec::Kind::anchored) {
      model_.bolt_springs.push_back(
          {index, inside.front().block, inside.back().block, bolt.from, bolt.to, axis});
      return;
    }
    for (std::size_t n = 1; n < inside.size(); ++n) {
      const Vec2 p = bolt.from + inside[n - 1].t1 * (bolt.to - bolt.from);
      model_.bolt_springs.push_back({index, inside[n - 1].block, inside[n].block, p, p, axis});
    }
  }

  Model& model_;
  const std::vector<BoltSpec>& bolts_;
  std::vector<BBox> boxes_;                   // per block
  std::map<int, std::vector<char>> present_;  // stage -> blocks present during it
};

}  // namespace

void add_bolts(Model& model, const std::vector<BoltSpec>& bolts) {
  if (bolts.empty())
    return;
  BoltBuilder(model, bolts).resolve();
}

std::vector<char> springs_present(const Model& model, int stage) {
  if (stage == -1)
    return std::vector<char>(model.bolt_springs.size(), 0);
  const std::vector<char> blocks = blocks_present(model, stage);  // out_of_range for no stage
  std::vector<char> present(model.bolt_springs.size(), 0);
  for (std::size_t n = 0; n < present.size(); ++n) {
    const BoltSpring& s = model.bolt_springs[n];
    const Bolt& bolt = model.bolts[static_cast<std::size_t>(s.bolt)];
    present[n] = bolt.stage <= stage && blocks[static_cast<std::size_t>(s.block_a)] &&
                 blocks[static_cast<std::size_t>(s.block_b)];
  }
  return present;
}

}  // namespace bimrock
