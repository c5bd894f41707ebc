#include <bimrock/petsc/elastic_solve.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <petscksp.h>

#include <bimrock/analysis/support_check.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/petsc/distributed_stiffness.hpp>
#include <bimrock/petsc/owned.hpp>
#include <bimrock/petsc/petsc_call.hpp>

namespace bimrock {
namespace {

// The PETSc objects of one solve, destroyed in every case.
struct Objects {
  Vec p = nullptr;
  Vec residual = nullptr;
  Vec u = nullptr;
  Vec u_all = nullptr;
  KSP ksp = nullptr;
  MatNullSpace modes = nullptr;
  VecScatter gather = nullptr;
  std::vector<Vec> mode_vectors;
  ~Objects() {
    for (Vec& v : mode_vectors)
      VecDestroy(&v);
    VecScatterDestroy(&gather);
    MatNullSpaceDestroy(&modes);
    KSPDestroy(&ksp);
    VecDestroy(&u_all);
    VecDestroy(&u);
    VecDestroy(&residual);
    VecDestroy(&p);
  }
};

// Rigid-body mode k of a block whose centroid is r from the centre, in its unknowns
// [u0, v0, theta, eps_x, eps_y, gamma_xy]: translations along x (k = 0) and y (1), and a unit
// rotation about the centre (2): u = -theta y, v = theta x at the centroid.
std::array<double, 6> rigid_body_mode(std::size_t k, const Vec2& r) {
  if (k == 0)
    return {1.0, 0.0, 0.0, 0.0, 0.0, 0.0};
  if (k == 1)
    return {0.0, 1.0, 0.0, 0.0, 0.0, 0.0};
  return {-r.y(), r.x(), 1.0, 0.0, 0.0, 0.0};
}

std::string method(KSP ksp, PC pc) {
  KSPType ksp_type = nullptr;
  PCType pc_type = nullptr;
  petsc_call(KSPGetType(ksp, &ksp_type), "KSPGetType");
  petsc_call(PCGetType(pc, &pc_type), "PCGetType");
  MatSolverType factor = nullptr;
  if (std::string(pc_type) == PCCHOLESKY || std::string(pc_type) == PCLU)
    petsc_call(PCFactorGetMatSolverType(pc, &factor), "PCFactorGetMatSolverType");
  return factor == nullptr ? fmt::format("{} + {}", ksp_type, pc_type)
                           : fmt::format("{} + {} ({})", ksp_type, pc_type, factor);
}

}  // namespace

Eigen::VectorXd petsc_solve(Mat k, const Eigen::VectorXd& p, const std::vector<Vec2>& centroids,
                            const BlockRange& mine, PetscSolveReport& report) {
  MPI_Comm_size(PETSC_COMM_WORLD, &report.ranks);
  const auto blocks = static_cast<std::int64_t>(centroids.size());
  const auto n = static_cast<PetscInt>(p.size());
  Objects o;

  // The near-null space of the blocks without supports: two translations and a rotation about
  // the centroids' mean, orthonormal as PETSc asks (the centred rotation is orthogonal to both
  // translations).
  Vec2 mean(0.0, 0.0);
  for (const Vec2& c : centroids)
    mean += c;
  mean /= static_cast<double>(std::max<std::int64_t>(blocks, 1));
  o.mode_vectors.resize(3, nullptr);
  for (std::size_t index = 0; index < o.mode_vectors.size(); ++index) {
    Vec& mode = o.mode_vectors[index];
    petsc_call(VecCreateMPI(PETSC_COMM_WORLD, static_cast<PetscInt>(mine.rows()), n, &mode),
               "VecCreateMPI");
    PetscScalar* v = nullptr;
    petsc_call(VecGetArray(mode, &v), "VecGetArray");
    for (std::int64_t b = mine.first; b < mine.last; ++b) {
      const std::array<double, 6> d =
          rigid_body_mode(index, centroids[static_cast<std::size_t>(b)] - mean);
      std::copy(d.begin(), d.end(), v + 6 * (b - mine.first));
    }
    petsc_call(VecRestoreArray(mode, &v), "VecRestoreArray");
    petsc_call(VecNormalize(mode, nullptr), "VecNormalize");
  }
  petsc_call(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, 3, o.mode_vectors.data(), &o.modes),
             "MatNullSpaceCreate");
  petsc_call(MatSetNearNullSpace(k, o.modes), "MatSetNearNullSpace");

  petsc_call(MatCreateVecs(k, &o.u, &o.p), "MatCreateVecs");
  {
    PetscScalar* v = nullptr;
    petsc_call(VecGetArray(o.p, &v), "VecGetArray");
    for (std::int64_t i = 6 * mine.first; i < 6 * mine.last; ++i)
      v[i - 6 * mine.first] = p(i);
    petsc_call(VecRestoreArray(o.p, &v), "VecRestoreArray");
  }

  petsc_call(KSPCreate(PETSC_COMM_WORLD, &o.ksp), "KSPCreate");
  petsc_call(KSPSetOperators(o.ksp, k, k), "KSPSetOperators");
  petsc_call(KSPSetType(o.ksp, KSPCG), "KSPSetType");
  // Converged on the true residual |P - K u| <= rtol |P|, not the preconditioned one.
  petsc_call(KSPSetNormType(o.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  PC pc = nullptr;
  petsc_call(KSPGetPC(o.ksp, &pc), "KSPGetPC");
  // Smoothed-aggregation multigrid: Trilinos' ML where PETSc has it (27 iterations on a
  // 10 000-block mass, where PETSc's own GAMG takes 48: docs/parallel.md), else GAMG. Both
  // coarsen with the near-null space set above.
#ifdef PETSC_HAVE_ML
  petsc_call(PCSetType(pc, PCML), "PCSetType");
#else
  petsc_call(PCSetType(pc, PCGAMG), "PCSetType");
#endif
  // Each level smoothed by point-block Jacobi: a block's six unknowns solved together (their
  // 6 x 6 diagonal block of K inverted), as they are coupled far more strongly to each other
  // than to a neighbour's. Point-wise smoothers (ML's SOR, GAMG's Jacobi) take 243 and 609
  // iterations on the mass above. The levels' smoothers are made when the preconditioner is set
  // up, from the options database: the default goes there, unless PETSC_OPTIONS chose one.
  PetscBool smoother_chosen = PETSC_FALSE;
  petsc_call(PetscOptionsHasName(nullptr, nullptr, "-mg_levels_pc_type", &smoother_chosen),
             "PetscOptionsHasName");
  if (!smoother_chosen)
    petsc_call(PetscOptionsSetValue(nullptr, "-mg_levels_pc_type", PCPBJACOBI),
               "PetscOptionsSetValue");
  petsc_call(KSPSetTolerances(o.ksp, kPetscRelativeTolerance, 0.0, PETSC_DEFAULT, kPetscIterations),
             "KSPSetTolerances");
  petsc_call(KSPSetFromOptions(o.ksp), "KSPSetFromOptions");  // PETSC_OPTIONS may change any of it
  // The multigrid set up before CG's work vectors exist: its temporaries and those vectors are
  // not held at once (the peak of a 10^6-block run).
  petsc_call(PCSetUp(pc), "PCSetUp");
  petsc_call(KSPSolve(o.ksp, o.p, o.u), "KSPSolve");
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  petsc_call(KSPGetConvergedReason(o.ksp, &reason), "KSPGetConvergedReason");
  PetscInt iterations = 0;
  petsc_call(KSPGetIterationNumber(o.ksp, &iterations), "KSPGetIterationNumber");
  report.iterations = static_cast<int>(iterations);
  report.method = method(o.ksp, pc);

  // Where the iterations fail (K ill-conditioned: penalty interfaces), MUMPS factorizes K
  // across the processes instead, unless the user chose the method in PETSC_OPTIONS.
  PetscBool chosen = PETSC_FALSE;
  PetscBool pc_chosen = PETSC_FALSE;
  petsc_call(PetscOptionsHasName(nullptr, nullptr, "-ksp_type", &chosen), "PetscOptionsHasName");
  petsc_call(PetscOptionsHasName(nullptr, nullptr, "-pc_type", &pc_chosen), "PetscOptionsHasName");
  if (reason < 0 && !chosen && !pc_chosen) {
    report.fallback = fmt::format("{} stopped: {} after {} iterations", report.method,
                                  KSPConvergedReasons[reason], report.iterations);
    petsc_call(KSPSetType(o.ksp, KSPPREONLY), "KSPSetType");
    petsc_call(PCSetType(pc, PCCHOLESKY), "PCSetType");
    petsc_call(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    petsc_call(KSPSolve(o.ksp, o.p, o.u), "KSPSolve");
    petsc_call(KSPGetConvergedReason(o.ksp, &reason), "KSPGetConvergedReason");
    petsc_call(KSPGetIterationNumber(o.ksp, &iterations), "KSPGetIterationNumber");
    report.iterations = static_cast<int>(iterations);
    report.method = method(o.ksp, pc);
  }
  // Every process gets the whole u (its ranks' ranges in order: the numbering of the blocks).
  petsc_call(VecScatterCreateToAll(o.u, &o.gather, &o.u_all), "VecScatterCreateToAll");
  petsc_call(VecScatterBegin(o.gather, o.u, o.u_all, INSERT_VALUES, SCATTER_FORWARD),
             "VecScatterBegin");
  petsc_call(VecScatterEnd(o.gather, o.u, o.u_all, INSERT_VALUES, SCATTER_FORWARD),
             "VecScatterEnd");
  Eigen::VectorXd u(n);
  const PetscScalar* all = nullptr;
  petsc_call(VecGetArrayRead(o.u_all, &all), "VecGetArrayRead");
  for (PetscInt i = 0; i < n; ++i)
    u(i) = all[i];
  petsc_call(VecRestoreArrayRead(o.u_all, &all), "VecRestoreArrayRead");
  // The true residual of u: what the solve achieved, whatever norm PETSC_OPTIONS made it stop
  // on.
  petsc_call(VecDuplicate(o.p, &o.residual), "VecDuplicate");
  petsc_call(MatMult(k, o.u, o.residual), "MatMult");
  petsc_call(VecAYPX(o.residual, -1.0, o.p), "VecAYPX");
  PetscReal residual_norm = 0.0;
  PetscReal p_norm = 0.0;
  petsc_call(VecNorm(o.residual, NORM_2, &residual_norm), "VecNorm");
  petsc_call(VecNorm(o.p, NORM_2, &p_norm), "VecNorm");
  report.relative_residual = residual_norm / std::max(p_norm, 1e-300);
  if (reason < 0)
    throw ModelError(
        fmt::format("the PETSc solver ({}) did not converge: {} after {} iterations, relative "
                    "residual {:.3g}; solve with CHOLMOD (without --solver petsc), or choose "
                    "another method in PETSC_OPTIONS (docs/parallel.md)",
                    report.method, KSPConvergedReasons[reason], report.iterations,
                    report.relative_residual),
        {});
  return u;
}

ElasticSolution solve_elastic_with_petsc(const Model& model, PetscSolveReport& report) {
  ElasticSolution s;
  {
    ScopedTimer t(s.timings, "check supports");
    check_supports(model);
  }
  BlockPartition partition;
  {
    ScopedTimer t(s.timings, "partition");
    partition = partition_blocks(model);
  }
  Owned<Mat, MatDestroy> k;
  Eigen::VectorXd p;
  {
    ScopedTimer t(s.timings, "assemble");
    *k.out() = assemble_distributed_stiffness(model, partition);
    p = assemble_loads(model, model.loads);
  }
  {
    ScopedTimer t(s.timings, "solve (PETSc)");
    // P, the centroids and u in the partition's numbering of the blocks.
    Eigen::VectorXd p_numbered(p.size());
    std::vector<Vec2> centroids(model.blocks.size());
    for (std::size_t n = 0; n < partition.block.size(); ++n) {
      const int b = partition.block[n];
      p_numbered.segment<6>(6 * static_cast<Eigen::Index>(n)) = p.segment<6>(6 * b);
      centroids[n] = model.blocks[static_cast<std::size_t>(b)].centroid;
    }
    p.resize(0);
    const Eigen::VectorXd u = petsc_solve(k.get(), p_numbered, centroids, partition.mine, report);
    s.u.resize(u.size());
    for (std::size_t n = 0; n < partition.block.size(); ++n)
      s.u.segment<6>(6 * partition.block[n]) = u.segment<6>(6 * static_cast<Eigen::Index>(n));
  }
  {
    ScopedTimer t(s.timings, "evaluate");
    evaluate_fields(model, s);
  }
  return s;
}

}  // namespace bimrock
