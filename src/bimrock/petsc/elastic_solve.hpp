#pragma once
/// @file The elastic analysis on PETSc (docs/parallel.md): K u = P solved by conjugate gradients
/// preconditioned by smoothed-aggregation algebraic multigrid (ML, or GAMG), across the processes
/// of an MPI run, instead of by K's Cholesky factor. Every process holds the model and assembles
/// the rows of K of its own blocks (distributed_stiffness.hpp); every process gets the whole u
/// back, so that the results are evaluated and written as those of the serial analysis.
#include <string>

#include <Eigen/Core>

#include <petscmat.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/petsc/distributed_stiffness.hpp>

namespace bimrock {

/// How the iterative solve ended.
struct PetscSolveReport {
  int ranks = 1;
  int iterations = 0;
  double relative_residual = 0.0;  ///< |P - K u| / |P| of the returned u
  std::string method;              ///< KSP and PC types, after PETSC_OPTIONS
  std::string fallback;            ///< why the iterative method gave way to MUMPS, or empty
};

/// The relative tolerance of the residual the iterations stop at: the displacements of the
/// jointed examples then agree with the direct solve's to 3e-10 (docs/parallel.md).
inline constexpr double kPetscRelativeTolerance = 1e-12;
/// The iterations allowed before MUMPS takes over: jointed masses converge in 22-36, from 105
/// to 10^6 blocks (docs/parallel.md), and where penalty interfaces defeat the iterations they
/// stall or diverge.
inline constexpr int kPetscIterations = 500;

/// u = K^-1 P with PETSc on PETSC_COMM_WORLD, in the partition's numbering of the blocks. `k`
/// holds this process's rows of K (those of its blocks, `mine`: assemble_distributed_stiffness);
/// `p` is the whole P, on every process, and so is the returned u. `centroids` are the blocks',
/// for the rigid-body modes the multigrid coarsens with. Where the iterations do not converge,
/// K is factorized by MUMPS (Cholesky) across the processes, unless PETSC_OPTIONS sets
/// -ksp_type or -pc_type; throws ModelError, saying what to do, when the method chosen there
/// does not converge.
Eigen::VectorXd petsc_solve(Mat k, const Eigen::VectorXd& p, const std::vector<Vec2>& centroids,
                            const BlockRange& mine, PetscSolveReport& report);

/// solve_elastic (analysis/elastic_analysis.hpp) with the solve above: the same solution, to
/// the solver's tolerance; ElasticSolution::factor_nonzeros is 0.
ElasticSolution solve_elastic_with_petsc(const Model& model, PetscSolveReport& report);

}  // namespace bimrock
