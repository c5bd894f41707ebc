#pragma once
/// @file The plastic analysis on the PETSc backend (docs/parallel.md): K factorized by MUMPS
/// (Cholesky) across the processes of an MPI run, its rows assembled by each process
/// (distributed_stiffness.hpp). Every process runs the same analysis on the same data; where it
/// solves with K or condenses K onto a region, all of them call the factor together and all get
/// the same answer (the solution gathered to each, the region's S broadcast). What stays in each
/// process is the work on the plastic zone: the zones condensed from a region's S, the LCPs.
///
/// A region R is condensed through its boundary B (the blocks of R coupled to one outside it):
/// only B's rows of K couple to the rest E, so
///
///   S_R = K_RR - K_RE K_EE^-1 K_ER   differs from K_RR only in its B x B block,
///   S_BB = K_BB - K_BE K_EE^-1 K_EB,
///
/// the Schur complement onto B of K with R's interior decoupled (its rows and columns set to
/// those of the identity). MUMPS factorizes that matrix with B last and returns S_BB, dense, to
/// the first process: one distributed factorization per region, as CHOLMOD's is one
/// factorization of K in a new order.
#include <memory>

#include <bimrock/model/model.hpp>
#include <bimrock/petsc/distributed_stiffness.hpp>
#include <bimrock/solve/stiffness_factor.hpp>

namespace bimrock {

/// The factorization to give run_plastic_analysis (PlasticTuning::stiffness) on every process
/// of PETSC_COMM_WORLD: the blocks partitioned once (partition_blocks), K of what stands
/// factorized by MUMPS for each stage structure. `model` must outlive it. Where K is singular,
/// the block left free is named (ModelError), as without the backend.
[[nodiscard]] StiffnessFactorization distributed_factorization(const Model& model);

/// K of `present` condensed onto `region` by the boundary Schur complement above: S's lower
/// triangle in the unknowns of the region's blocks in ascending order (6 each), on every
/// process. `lower` is K's lower triangle (model numbering), `k` the same K distributed.
[[nodiscard]] SparseMatrix condense_onto_region(const Model& model, const BlockPartition& partition,
                                                Mat k, const SparseMatrix& lower,
                                                const std::vector<char>& region);

}  // namespace bimrock
