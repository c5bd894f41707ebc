#pragma once
/// @file VTK XML files that ParaView opens: one UnstructuredGrid (.vtu) per step, with the
/// blocks as polygon cells, the interfaces and the standing bolt springs as line cells, and a
/// .pvd series over the steps.
/// Every cell has its own points (blocks do not share corners: they move apart), so the
/// displacement point array, applied with "Warp By Vector", shows opened joints as gaps.
/// Arrays are inline binary (Base64), as VTK writes them: exact, and fast to write.
#include <filesystem>
#include <string>
#include <vector>

#include <bimrock/analysis/elastic_analysis.hpp>

namespace bimrock {

/// Cell arrays (one value per cell; a field that does not apply to a cell's kind is 0 there):
///  kind (0 block, 1 interface, 2 bolt spring), id (block, interface or spring index), material
///  (a spring's: its bolt's index),
///  stress [sigma_x, sigma_y, tau_xy] Pa, strain [eps_x, eps_y, gamma_xy], plastic_strain,
///  block_state (0 elastic, 1 yielded),
///  sigma_n, tau (Pa, mean of the two integration points), delta_n, delta_s (m, mean),
///  plastic_delta [n, s] (m, mean), interface_state (0 elastic, 1 slipped, 2 open),
///  bolt_force [axial, shear] (N per bolt, axial > 0 tension), bolt_state (0 elastic, 1 yielded).
/// Point arrays: displacement [ux, uy, 0] (m); with `mechanism`, also mechanism_velocity
/// [vx, vy, 0]: Q(x, y) times the block's 6 entries of the mechanism (dimensionless; an
/// interface's points take block i's).
/// @param plastic the plastic state of a nonlinear analysis (empty for an elastic one)
/// @param mechanism the velocities of a collapse mechanism, 6 per block (normalized:
///   MechanismBlocks), or nullptr for none
void write_vtu(const Model& model, const ElasticSolution& fields, const PlasticParts& plastic,
               const std::filesystem::path& file, const Eigen::VectorXd* mechanism = nullptr);

struct PvdEntry {
  double time = 0.0;  ///< shown by ParaView as the time of the step (e.g. the load factor)
  std::string file;   ///< relative to the .pvd
};

void write_pvd(const std::vector<PvdEntry>& steps, const std::filesystem::path& file);

}  // namespace bimrock
