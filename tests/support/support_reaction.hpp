#pragma once
// The force the supports exert on a structure, integrated from the support springs' stresses:
// independent of how the increments were solved, it must balance the applied loads.
#include <Eigen/Core>

#include <bimrock/analysis/field_results.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock::testing {

/// The stress vector sigma_n n + tau s of each support spring on its block, integrated along the
/// support (both points weigh half its length, as the springs do).
inline Vec2 support_reaction(const Model& model, const Eigen::VectorXd& u,
                             const PlasticParts& plastic) {
  Vec2 total = Vec2::Zero();
  for (int k = 0; k < static_cast<int>(model.interfaces.size()); ++k) {
    const Interface& f = model.interfaces[static_cast<std::size_t>(k)];
    if (!f.is_support())
      continue;
    const Vec2 s(-f.normal.y(), f.normal.x());
    const double w = 0.5 * f.segment.length() * model.settings.thickness;
    for (const InterfacePointState& p : interface_state(model, k, u, plastic))
      total += w * (p.stress(0) * f.normal + p.stress(1) * s);
  }
  return total;
}

}  // namespace bimrock::testing
