#include <bimrock/analysis/strength_reduction.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace bimrock {
namespace {

Softening divided(Softening law, double factor) {
  law.peak /= factor;
  law.residual /= factor;
  return law;
}

// sin of the angle whose tangent is tan(asin(s)) / factor.
double reduced_sine(double sine, double factor) {
  const double angle = std::atan(std::tan(std::asin(sine)) / factor);
  return std::sin(angle);
}

}  // namespace

StrengthSelection all_strengths(const Model& model) {
  StrengthSelection s;
  for (const JointMaterial& m : model.joint_materials)
    s.joint_materials.push_back(m.strength ? 1 : 0);
  for (const BlockMaterial& m : model.block_materials)
    s.block_materials.push_back(m.strength ? 1 : 0);
  return s;
}

Model reduce_strength(const Model& model, const StrengthSelection& selection, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor))
    throw std::invalid_argument("reduce_strength: the factor must be positive and finite");
  Model reduced = model;
  for (std::size_t m = 0; m < reduced.joint_materials.size(); ++m) {
    std::optional<JointStrength>& s = reduced.joint_materials[m].strength;
    if (!s || m >= selection.joint_materials.size() || !selection.joint_materials[m])
      continue;
    const bool associated =
        s->dilation == s->friction.peak && s->friction.peak == s->friction.residual;
    s->cohesion = divided(s->cohesion, factor);
    s->friction = divided(s->friction, factor);
    s->tensile = divided(s->tensile, factor);
    s->dilation = associated ? s->friction.peak : std::min(s->dilation, s->friction.peak);
  }
  for (std::size_t m = 0; m < reduced.block_materials.size(); ++m) {
    std::optional<BlockStrength>& s = reduced.block_materials[m].strength;
    if (!s || m >= selection.block_materials.size() || !selection.block_materials[m])
      continue;
    const bool associated = s->dilation == s->friction;
    s->cohesion /= factor;
    s->friction = reduced_sine(s->friction, factor);
    s->dilation = associated ? s->friction : std::min(s->dilation, s->friction);
  }
  return reduced;
}

Model with_associated_flow(const Model& model) {
  Model associated = model;
  for (JointMaterial& m : associated.joint_materials)
    if (m.strength)
      m.strength->dilation = m.strength->friction.peak;
  for (BlockMaterial& m : associated.block_materials)
    if (m.strength)
      m.strength->dilation = m.strength->friction;
  return associated;
}

bool has_softening(const Model& model) {
  const auto softens = [](const Softening& law) { return law.residual < law.peak; };
  return std::any_of(
      model.joint_materials.begin(), model.joint_materials.end(), [&](const JointMaterial& m) {
        return m.strength && (softens(m.strength->cohesion) || softens(m.strength->friction) ||
                              softens(m.strength->tensile));
      });
}

}  // namespace bimrock
