#pragma once
// The benchmark models: reference/reference_cases.hpp's brick mass under gravity, elastic or with
// plastic joints.
#include <cmath>

#include <bimrock/reference/reference_cases.hpp>

namespace bimrock::bench {

inline CaseSpec brick_mass_case(int n_blocks) {
  return bimrock::brick_mass_case(n_blocks);
}

/// The brick mass with Mohr-Coulomb joints (cohesion 0.1 MPa, friction 35 deg, no dilation:
/// non-associated flow) and tensile strength `tensile` [Pa], its gravity applied in `increments`
/// equal steps of one stage. With no tensile strength the vertical joints of the free-standing
/// mass carry no normal stress and most of them open: large LCPs.
inline CaseSpec plastic_brick_mass_case(int n_blocks, double tensile, int increments) {
  CaseSpec c = bimrock::brick_mass_case(n_blocks);
  JointStrength s;
  s.cohesion = Softening::constant(0.1e6);
  s.friction = Softening::constant(std::tan(35.0 * M_PI / 180.0));
  s.dilation = 0.0;
  s.tensile = Softening::constant(tensile);
  c.joint_materials[0].strength = s;
  StageSpec gravity{"gravity", c.loads, increments, std::nullopt, {0, "gravity"}};
  c.loads = {};
  c.stages = {gravity};
  return c;
}

}  // namespace bimrock::bench
