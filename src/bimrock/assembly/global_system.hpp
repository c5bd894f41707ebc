#pragma once
/// @file Scattering local blocks into the global stiffness K and load vector P (eq. 14).
/// Global unknowns: U = [d_0; d_1; ...], block k owns rows 6k .. 6k+5.
#include <cstdint>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <bimrock/model/model.hpp>
#include <bimrock/model/presence.hpp>

namespace bimrock {

/// 64-bit indices: a 10^6-block K has more non-zeros than an int counts in its factor.
using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, std::int64_t>;

/// The lower triangle of K (K is symmetric; CHOLMOD reads one triangle) of every block, without
/// bolts.
SparseMatrix assemble_stiffness_lower(const Model& model);

/// The same of what stands in a stage (after an excavation, with the bolts installed): the same
/// pattern (so a factor's analysis carries over), with the stiffness of an absent block, of
/// every interface touching one and of every absent spring left out, and an absent block's six
/// unknowns held by a decoupled diagonal (its displacement stays what it was).
SparseMatrix assemble_stiffness_lower(const Model& model, const Presence& present);

/// The whole symmetric K, for checks and small problems.
SparseMatrix full_from_lower(const SparseMatrix& lower);

/// P of eq. 14 for the model's loads: body forces t A gamma g (exact: first moments about the
/// centroid vanish), point loads Q(p)^T F, tractions t * integral Q^T tr ds (2-point Gauss, exact).
Eigen::VectorXd assemble_loads(const Model& model, const Loads& loads);

}  // namespace bimrock
