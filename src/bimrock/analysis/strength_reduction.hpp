#pragma once
/// @file Strength reduction: the strengths of a model divided by a factor F, as the factor of
/// safety of a slope or a foundation is defined (c / F, tan(phi) / F, sigma_t / F). The stiffness
/// does not depend on strength, so every reduced model shares the factor of K.
#include <vector>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// Which materials have their strength reduced (per material of the model: true where reduced).
struct StrengthSelection {
  std::vector<char> joint_materials;
  std::vector<char> block_materials;
};

/// Every material that has a strength law.
StrengthSelection all_strengths(const Model& model);

/// The model with the strengths of the selected materials divided by `factor` (> 0): cohesion
/// and tensile strength by F, tan(phi) by F (block materials: phi' = atan(tan(phi) / F)), peak
/// and residual values alike. The dilation is kept unless it would exceed the reduced friction
/// angle, where it becomes that angle (a flow rule never more dilatant than associated flow);
/// associated flow stays associated, its dilation following the friction (raised too where
/// F < 1).
Model reduce_strength(const Model& model, const StrengthSelection& selection, double factor);

/// The model with associated flow: each dilation angle (of joints and blocks) set to its
/// friction angle, every strength kept. By the static theorem of limit analysis, whatever the
/// flow rule, a state the model carries has stresses within the yield surfaces, so no load above
/// the collapse load of this model is carried by the original one (Radenkovic's first theorem),
/// as long as no strength softens (has_softening()).
Model with_associated_flow(const Model& model);

/// Whether a strength of the model falls with plastic flow (a residual value below the peak).
bool has_softening(const Model& model);

}  // namespace bimrock
