#pragma once
/// @file Strength laws of joints and blocks (eqs. 17-21, 33): small immutable value types.
/// Units: Pa for cohesion and tensile strength, metres for plastic slip and opening.
#include <algorithm>
#include <cmath>
#include <limits>

namespace bimrock {

/// A strength parameter that softens (or hardens) linearly with an accumulated plastic measure
/// kappa from `peak` to `residual`, reached at kappa = `distance` (0: at once, brittle;
/// infinity: never, perfectly plastic).
struct Softening {
  double peak = 0.0;
  double residual = 0.0;
  double distance = std::numeric_limits<double>::infinity();

  [[nodiscard]] static Softening constant(double value) {
    return {value, value, std::numeric_limits<double>::infinity()};
  }
  [[nodiscard]] double value(double kappa) const {
    if (kappa >= distance)
      return residual;
    return peak + (residual - peak) * (kappa / distance);
  }
  /// Relative distance to the kink within which kappa counts as having reached it: a step cut
  /// at the kink lands there only to round-off, and the next step must take the residual slope.
  static constexpr double kKinkTolerance = 1e-9;
  /// d value / d kappa at kappa, for the next increment (0 once the residual is reached).
  [[nodiscard]] double slope(double kappa) const {
    if (kappa >= distance * (1.0 - kKinkTolerance) || !std::isfinite(distance))
      return 0.0;
    return (residual - peak) / distance;
  }
};

/// Mohr-Coulomb with tension cut-off on a joint, in interface stresses R = [sigma_n, tau]
/// (tension positive):  f_+- = +-tau + sigma_n tan(phi) - c <= 0,  f_t = sigma_n - sigma_t <= 0.
/// Slip flows along [tan(psi), +-1] (psi: dilation, non-associated when psi != phi); opening
/// along [1, 0] and reversible (the joint closes again, never penetrates; eqs. 31-34).
/// c and tan(phi) soften with accumulated plastic slip, sigma_t with the largest opening.
struct JointStrength {
  Softening cohesion = Softening::constant(0.0);  ///< c [Pa]
  Softening friction = Softening::constant(0.0);  ///< tan(phi) [-]
  double dilation = 0.0;                          ///< tan(psi) [-]
  Softening tensile = Softening::constant(0.0);   ///< sigma_t [Pa]
};

/// Yield criterion of a block's mean stress, linearized in plane strain as a polygon of `planes`
/// planes in the ((s_x - s_y)/2, tau_xy) plane, inscribed in the Mohr-Coulomb (or Tresca) circle
/// (so never stronger than the exact criterion: at most 1 - cos(pi/planes) weaker).
struct BlockStrength {
  enum class Criterion { mohr_coulomb, tresca };
  Criterion criterion = Criterion::mohr_coulomb;
  double cohesion = 0.0;  ///< c [Pa] (Tresca: the undrained strength)
  double friction = 0.0;  ///< sin(phi) [-] (0 for Tresca)
  double dilation = 0.0;  ///< sin(psi) [-]
  int planes = 24;
};

}  // namespace bimrock
