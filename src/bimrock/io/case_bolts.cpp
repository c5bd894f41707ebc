/// @file The bolts section: rock bolts and anchors, each a bar from its head to its far end,
/// installed at the start of a stage. The reader checks each value's form and magnitude;
/// ranges, the stage's name and the line through the blocks are checked by add_bolts().
#include <bimrock/io/case_sections.hpp>

#include <string_view>

namespace bimrock::case_file {
namespace {

// [N/m]: as stiff as the stiffest joint spring over a square metre; larger values overflow.
constexpr double kMaxBoltStiffness = kMaxStiffness;

/// One bolt: kind, from, to [m], axial_stiffness [N/m], capacity [N]; name, pretension [N],
/// shear_stiffness [N/m], shear_capacity [N], spacing [m], install (a stage's name). The line of
/// each key given is kept for add_bolts()' messages.
BoltSpec read_bolt(const Value& v) {
  const Map m = open(v, "bolts[]");
  BoltSpec b;
  b.source = v.ref();
  b.lines[v.item()] = v.line();
  const auto remember = [&](const Value& x) {
    b.lines[x.item()] = x.line();
    return x;
  };
  const auto force = [](const Value& x) { return bounded(x, kMaxForce, "N", kLarger); };
  const auto stiffness = [](const Value& x) {
    return bounded(x, kMaxBoltStiffness, "N/m", kStiffer);
  };
  if (const auto x = m.find("name"))
    b.name = name(remember(*x));
  b.kind = choice<BoltSpec::Kind>(remember(m.at("kind")), {{"anchored", BoltSpec::Kind::anchored},
                                                           {"grouted", BoltSpec::Kind::grouted}});
  b.from = location(remember(m.at("from")));
  b.to = location(remember(m.at("to")));
  b.axial_stiffness = stiffness(remember(m.at("axial_stiffness")));
  b.capacity = force(remember(m.at("capacity")));
  if (const auto x = m.find("pretension"))
    b.pretension = force(remember(*x));
  if (const auto x = m.find("shear_stiffness"))
    b.shear_stiffness = stiffness(remember(*x));
  if (const auto x = m.find("shear_capacity"))
    b.shear_capacity = force(remember(*x));
  if (const auto x = m.find("spacing"))
    b.spacing = bounded(remember(*x), kMaxCoordinate, "m", "the model's extent");
  if (const auto x = m.find("install"))
    b.install = name(remember(*x));
  return b;
}

}  // namespace

/// bolts: a list of bolts, in the order of their springs and of the results.
std::vector<BoltSpec> read_bolts(const Value& v) {
  return read_list(v, read_bolt);
}

}  // namespace bimrock::case_file
