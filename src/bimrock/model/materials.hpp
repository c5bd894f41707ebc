#pragma once
/// @file Elastic material laws of blocks and joints (SI: Pa, Pa/m, N/m^3, m).
#include <optional>
#include <string>

#include <Eigen/Core>

#include <bimrock/model/errors.hpp>
#include <bimrock/model/strength.hpp>

namespace bimrock {

enum class PlaneMode { strain, stress };

/// An isotropic linear elastic rock.
struct BlockMaterial {
  std::string name;
  double young = 0.0;        ///< E [Pa]
  double poisson = 0.0;      ///< nu [-], 0 <= nu < 0.5
  double unit_weight = 0.0;  ///< gamma [N/m^3]; gravity loads are gamma * direction
  SourceRef source;
  std::optional<BlockStrength> strength;  ///< none: the block stays elastic
};

/// Elasticity matrix D_b of eq. 2 for [eps_x, eps_y, gamma_xy] (engineering shear strain).
Eigen::Matrix3d elasticity_matrix(const BlockMaterial& m, PlaneMode plane);

/// How the springs of an interface are integrated along its segment (docs/formulation.md).
enum class Integration {
  lobatto,  ///< end points (trapezoid rule): the default for joints; lets blocks topple exactly
  gauss,    ///< 2-point Gauss: exact elastic stiffness, for continuum interfaces that never open
};

/// The springs of a joint: normal and shear stiffness per unit length of joint.
struct JointMaterial {
  enum class Kind {
    springs,    ///< k_n, k_s given, or derived from a layer E, nu, h (eq. 7)
    continuum,  ///< penalty (eq. 15): k = penalty_factor * E / l from the adjacent blocks
  };
  std::string name;
  Kind kind = Kind::springs;
  double normal_stiffness = 0.0;  ///< k_n [Pa/m]
  double shear_stiffness = 0.0;   ///< k_s [Pa/m]
  double penalty_factor = 0.0;    ///< p [-], continuum only
  Integration integration = Integration::lobatto;
  int subdivisions = 1;  ///< each interface is split into this many equal pieces
  SourceRef source;
  std::optional<JointStrength> strength;  ///< none: the joint stays elastic (glued)
};

/// k_n and k_s of an interface layer of thickness h made of a material (E, nu), eq. 7.
/// Plane stress is the paper's formula; in plane strain the normal modulus is the constrained
/// modulus E (1 - nu) / ((1 + nu) (1 - 2 nu)) (the layer cannot strain along s or z).
struct SpringPair {
  double normal;
  double shear;
};
SpringPair layer_stiffness(double young, double poisson, double thickness, PlaneMode plane);

/// Default penalty factor p of continuum interfaces: k = p E / l. The patch test's stress error
/// falls like ~5/p until round-off takes over near p = 1e8 (tests/verification/patch_test.cpp):
/// 1e7 keeps it below 1e-6 with a decade of margin to round-off.
inline constexpr double kDefaultPenaltyFactor = 1e7;

}  // namespace bimrock
