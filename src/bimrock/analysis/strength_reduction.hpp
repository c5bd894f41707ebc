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
/// angle, where it becomes that angle (a flow rule never more dilatant than associated flow).
Model reduce_strength(const Model& model, const StrengthSelection& selection, double factor);

}  // namespace bimrock
