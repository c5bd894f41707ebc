#pragma once
// The patch test's problem (tests/verification/patch_test.cpp on generated blocks,
// gmsh_patch_test.cpp on an imported mesh): a rock in plane strain under the uniform biaxial
// traction (s_x, s_y). Its exact solution: that traction as a uniform stress (equilibrium), and
// the strain of Hooke's law in plane strain:
//   eps_x = ((1 - nu^2) s_x - nu (1 + nu) s_y) / E,
//   eps_y = ((1 - nu^2) s_y - nu (1 + nu) s_x) / E.
#include <Eigen/Core>

namespace bimrock::testing::patch {

inline constexpr double kE = 30e9;  // Young's modulus [Pa]
inline constexpr double kNu = 0.2;  // Poisson's ratio
// The normal tractions on the sides normal to x and to y, tension positive [Pa].
inline constexpr double kSx = 3e6;
inline constexpr double kSy = -2e6;

// (sigma_x, sigma_y, tau_xy) [Pa]
inline Eigen::Vector3d exact_stress() {
  return {kSx, kSy, 0.0};
}

// (eps_x, eps_y, gamma_xy)
inline Eigen::Vector3d exact_strain() {
  return {((1 - kNu * kNu) * kSx - kNu * (1 + kNu) * kSy) / kE,
          ((1 - kNu * kNu) * kSy - kNu * (1 + kNu) * kSx) / kE, 0.0};
}

}  // namespace bimrock::testing::patch
