#pragma once
/// @file What a displacement vector U means, block by block and interface by interface.
#include <array>
#include <vector>

#include <Eigen/Core>

#include <bimrock/analysis/analysis_state.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/plastic_state.hpp>
#include <bimrock/assembly/yield_points.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

struct BlockState {
  Vec6 d;                  ///< [u0, v0, theta, eps_x, eps_y, gamma_xy]
  Eigen::Vector3d strain;  ///< [eps_x, eps_y, gamma_xy]
  /// [sigma_x, sigma_y, tau_xy] = initial + D_b (strain - plastic) [Pa], tension positive
  Eigen::Vector3d stress;
  Eigen::Vector3d plastic = Eigen::Vector3d::Zero();  ///< plastic strain
};

struct InterfacePointState {
  Vec2 point;
  /// [delta_n, delta_s] [m], since its installation for an installed block's interface;
  /// delta_n > 0 opens
  Eigen::Vector2d delta;
  /// [sigma_n, tau] = initial + D_s (delta - plastic) [Pa]; sigma_n > 0 is tension
  Eigen::Vector2d stress;
  Eigen::Vector2d plastic = Eigen::Vector2d::Zero();  ///< plastic relative displacement [m]
};

/// Both integration points of the interface's rule.
using InterfaceState = std::array<InterfacePointState, 2>;

/// A bolt spring (docs/formulation.md, "Bolts"), per bolt.
struct SpringState {
  bool standing = false;  ///< installed, its two blocks present; else the rest is zero
  Eigen::Vector2d delta = Eigen::Vector2d::Zero();  ///< [elongation, shear] since installation [m]
  Eigen::Vector2d force = Eigen::Vector2d::Zero();  ///< [axial, shear] [N]; axial > 0 is tension
  Eigen::Vector2d plastic = Eigen::Vector2d::Zero();  ///< plastic [elongation, shear] [m]
  double capacity_used = 0.0;  ///< axial force over the tensile capacity (1: yielding in tension)
  bool yielded = false;        ///< it has flowed plastically
};

/// Plastic parts to subtract from the elastic strains, where a nonlinear analysis has them:
/// `plastic` of the yield point at each block / interface integration point (see
/// YieldPointIndex), or none; and the displacements at installation of the interfaces of
/// installed blocks, or none.
struct PlasticParts {
  const YieldPointIndex* index = nullptr;
  const std::vector<PlasticState>* states = nullptr;
  const InstalledInterfaces* installed = nullptr;
};

BlockState block_state(const Model& model, int block, const Eigen::VectorXd& u,
                       const PlasticParts& plastic = {});
InterfaceState interface_state(const Model& model, int interface, const Eigen::VectorXd& u,
                               const PlasticParts& plastic = {});

/// Every bolt spring's state; `standing` (per spring) says which stand.
std::vector<SpringState> spring_states(const Model& model, const std::vector<char>& standing,
                                       const Eigen::VectorXd& u, const PlasticParts& plastic);

/// Displacement u = Q(p) d of a block at point p (eq. 1).
Vec2 displacement_at(const Model& model, int block, const Vec2& p, const Eigen::VectorXd& u);

/// Mean strain [eps_x, eps_y, gamma_xy] of the whole mass, from its boundary displacements:
/// (1/A) closed integral sym(u (x) n) ds over the outline (docs/results.md), 2-point Gauss
/// (exact for the linear u along each edge). Equals the area-weighted block strains plus the
/// joint openings.
Eigen::Vector3d mean_strain(const Model& model, const Eigen::VectorXd& u);

/// Total area of the blocks [m^2].
double total_area(const Model& model);

}  // namespace bimrock
