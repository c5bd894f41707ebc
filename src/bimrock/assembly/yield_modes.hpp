#pragma once
/// @file The yield modes of one yield point, linearized at its current state (eqs. 20-23):
/// f = f0 + a^T D (E dU - sum_b g_b lambda_b) - sum_b h_ab lambda_b, mode by mode.
#include <array>

#include <Eigen/Core>

#include <bimrock/assembly/plastic_state.hpp>
#include <bimrock/assembly/yield_points.hpp>

namespace bimrock {

/// How the local strain of a yield point follows from the block unknowns:
/// interfaces delta = E [d_i; d_j] (E = B of eq. 5, 2 x 12, or 2 x 6 for a support);
/// blocks eps = E d (3 x 6); bolt springs [elongation, shear] = E [d_a; d_b] (2 x 12).
struct LocalOperator {
  Eigen::MatrixXd e;
  std::array<int, 2> blocks{0, kGround};  ///< blocks whose 6 unknowns E's columns act on
  [[nodiscard]] int n_blocks() const { return blocks[1] == kGround ? 1 : 2; }
};

LocalOperator local_operator(const Model& model, const YieldPoint& p);

/// D_s = diag(k_n, k_s) of the point's interface, D_b of its block, or diag(axial, shear) of a
/// bolt spring.
Eigen::MatrixXd local_stiffness(const Model& model, const YieldPoint& p);

/// The local strain (delta or eps) of the point for the unknowns u.
Eigen::VectorXd local_strain(const Model& model, const YieldPoint& p, const Eigen::VectorXd& u);

/// The stress (R = [sigma_n, tau] or [sigma_x, sigma_y, tau_xy]; a bolt spring's [axial,
/// shear] force) for the unknowns u: the initial stress plus the elastic part's (a bolt spring's
/// or an installed interface's displacement counted from its installation).
Eigen::VectorXd local_stress(const Model& model, const YieldPoint& p, const PlasticState& s,
                             const Eigen::VectorXd& u);

/// Mode kinds, for tags in reports: which way a joint yields, or a block facet.
enum class ModeKind {
  slip_positive,
  slip_negative,
  opening,
  block_facet,
  bolt_tension,
  bolt_shear_positive,
  bolt_shear_negative
};
ModeKind mode_kind(const YieldPoint& p, int mode);

/// Modes of one yield point: rows are modes, columns stress components.
struct LocalYield {
  Eigen::MatrixXd a;  ///< gradients df/dsigma
  Eigen::MatrixXd g;  ///< flow directions dG/dsigma
  Eigen::VectorXd f;  ///< yield function values at the current stress
  Eigen::MatrixXd h;  ///< hardening: h_ab = -(df_a/dkappa)(dkappa/dlambda_b); negative softens
};

/// The yield functions of a joint point at stress (sigma_n, tau): slip +, slip -, opening
/// (Mohr-Coulomb with a tension cut-off, softened by its state).
Eigen::Vector3d joint_values(const JointStrength& law, const PlasticState& s, double sigma_n,
                             double tau);

/// The yield functions of a bolt spring at its forces: tension (axial - capacity), and with a
/// shear capacity shear + and shear - (+-shear - shear capacity). Perfectly plastic.
Eigen::VectorXd bolt_values(const Bolt& bolt, double axial, double shear);

/// The planes of a block's linearized criterion: f_k = a_k . sigma - strength, flow g_k.
struct BlockPlanes {
  Eigen::MatrixXd a;
  Eigen::MatrixXd g;
  double strength = 0.0;  ///< c cos(phi) cos(pi / n)
};
BlockPlanes block_planes(const BlockStrength& law);

/// @param stress the point's current stress (local_stress)
LocalYield linearize(const Model& model, const YieldPoint& p, const PlasticState& s,
                     const Eigen::VectorXd& stress);

/// The index of the reversible opening mode of an interface point (its multiplier is the total
/// gap, not an increment: the joint can close again; eqs. 31-34).
inline constexpr int kOpeningMode = 2;

}  // namespace bimrock
