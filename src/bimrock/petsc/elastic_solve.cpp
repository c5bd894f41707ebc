#include <bimrock/petsc/elastic_solve.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <petscksp.h>

#include <bimrock/model/errors.hpp>

namespace bimrock {
namespace {

void check(PetscErrorCode code, const char* call) {
  if (code != 0)
    throw std::runtime_error(fmt::format("PETSc: {} failed with error code {}", call, code));
}

// The PETSc objects of one solve, destroyed in every case.
struct Objects {
  Mat k = nullptr;
  Vec p = nullptr;
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
    VecDestroy(&p);
    MatDestroy(&k);
  }
};

// This process's rows of the whole symmetric K, in compressed rows with global columns, from
// its lower triangle: row r holds (r, c) of column c < r, then column r itself (rows >= r).
// Both come out sorted by column as the columns are read in order.
struct LocalRows {
  std::vector<PetscInt> start;
  std::vector<PetscInt> columns;
  std::vector<PetscScalar> values;
};

LocalRows local_rows(const SparseMatrix& lower, std::int64_t first, std::int64_t last) {
  const std::int64_t m = last - first;
  std::vector<PetscInt> count(static_cast<std::size_t>(m), 0);
  const auto mine = [&](std::int64_t r) { return r >= first && r < last; };
  for (std::int64_t c = 0; c < std::min<std::int64_t>(lower.cols(), last); ++c) {
    for (SparseMatrix::InnerIterator it(lower, c); it; ++it) {
      if (mine(it.row()))
        ++count[static_cast<std::size_t>(it.row() - first)];
      if (mine(c) && it.row() != c)
        ++count[static_cast<std::size_t>(c - first)];
    }
  }
  LocalRows rows;
  rows.start.assign(static_cast<std::size_t>(m) + 1, 0);
  for (std::int64_t r = 0; r < m; ++r)
    rows.start[static_cast<std::size_t>(r) + 1] =
        rows.start[static_cast<std::size_t>(r)] + count[static_cast<std::size_t>(r)];
  rows.columns.resize(static_cast<std::size_t>(rows.start.back()));
  rows.values.resize(rows.columns.size());
  std::vector<PetscInt> next(rows.start.begin(), rows.start.end() - 1);
  const auto put = [&](std::int64_t r, std::int64_t c, double v) {
    const auto k = static_cast<std::size_t>(next[static_cast<std::size_t>(r - first)]++);
    rows.columns[k] = static_cast<PetscInt>(c);
    rows.values[k] = v;
  };
  for (std::int64_t c = 0; c < std::min<std::int64_t>(lower.cols(), last); ++c) {
    for (SparseMatrix::InnerIterator it(lower, c); it; ++it) {
      if (mine(it.row()) && it.row() != c)
        put(it.row(), c, it.value());  // (r, c), c < r: left of the diagonal
    }
    if (mine(c)) {
      for (SparseMatrix::InnerIterator it(lower, c); it; ++it)
        put(c, it.row(), it.value());  // row c from the diagonal on: column c of the lower part
    }
  }
  return rows;
}

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
  check(KSPGetType(ksp, &ksp_type), "KSPGetType");
  check(PCGetType(pc, &pc_type), "PCGetType");
  MatSolverType factor = nullptr;
  if (std::string(pc_type) == PCCHOLESKY || std::string(pc_type) == PCLU)
    check(PCFactorGetMatSolverType(pc, &factor), "PCFactorGetMatSolverType");
  return factor == nullptr ? fmt::format("{} + {}", ksp_type, pc_type)
                           : fmt::format("{} + {} ({})", ksp_type, pc_type, factor);
}

}  // namespace

Eigen::VectorXd petsc_solve(const SparseMatrix& lower, const Eigen::VectorXd& p,
                            const std::vector<Vec2>& centroids, PetscSolveReport& report) {
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  report.ranks = ranks;
  // Each process owns a contiguous range of blocks, of equal counts, and their six rows each.
  const auto blocks = static_cast<std::int64_t>(centroids.size());
  const std::int64_t first_block = blocks * rank / ranks;
  const std::int64_t last_block = blocks * (rank + 1) / ranks;
  const std::int64_t first = 6 * first_block;
  const std::int64_t last = 6 * last_block;
  const auto m = static_cast<PetscInt>(last - first);
  const auto n = static_cast<PetscInt>(lower.rows());

  Objects o;
  {
    const LocalRows rows = local_rows(lower, first, last);
    check(MatCreate(PETSC_COMM_WORLD, &o.k), "MatCreate");
    check(MatSetSizes(o.k, m, m, n, n), "MatSetSizes");
    check(MatSetType(o.k, MATAIJ), "MatSetType");
    check(MatSetBlockSize(o.k, 6), "MatSetBlockSize");  // a block's six unknowns: one node
    // The compressed rows preallocate and fill in one call; for one process the sequential
    // variant does it, and the other is then a no-op.
    check(MatSeqAIJSetPreallocationCSR(o.k, rows.start.data(), rows.columns.data(),
                                       rows.values.data()),
          "MatSeqAIJSetPreallocationCSR");
    check(MatMPIAIJSetPreallocationCSR(o.k, rows.start.data(), rows.columns.data(),
                                       rows.values.data()),
          "MatMPIAIJSetPreallocationCSR");
  }
  check(MatSetOption(o.k, MAT_SPD, PETSC_TRUE), "MatSetOption(MAT_SPD)");

  // The near-null space of the blocks without supports: two translations and a rotation about
  // the centroids' mean, orthonormal as PETSc asks (the centred rotation is orthogonal to both
  // translations).
  Vec2 mean(0.0, 0.0);
  for (const Vec2& c : centroids)
    mean += c;
  mean /= static_cast<double>(std::max<std::int64_t>(blocks, 1));
  o.mode_vectors.resize(3, nullptr);
  for (std::size_t k = 0; k < o.mode_vectors.size(); ++k) {
    Vec& mode = o.mode_vectors[k];
    check(VecCreateMPI(PETSC_COMM_WORLD, m, n, &mode), "VecCreateMPI");
    PetscScalar* v = nullptr;
    check(VecGetArray(mode, &v), "VecGetArray");
    for (std::int64_t b = first_block; b < last_block; ++b) {
      const std::array<double, 6> d =
          rigid_body_mode(k, centroids[static_cast<std::size_t>(b)] - mean);
      std::copy(d.begin(), d.end(), v + 6 * (b - first_block));
    }
    check(VecRestoreArray(mode, &v), "VecRestoreArray");
    check(VecNormalize(mode, nullptr), "VecNormalize");
  }
  check(MatNullSpaceCreate(PETSC_COMM_WORLD, PETSC_FALSE, 3, o.mode_vectors.data(), &o.modes),
        "MatNullSpaceCreate");
  check(MatSetNearNullSpace(o.k, o.modes), "MatSetNearNullSpace");

  check(MatCreateVecs(o.k, &o.u, &o.p), "MatCreateVecs");
  {
    PetscScalar* v = nullptr;
    check(VecGetArray(o.p, &v), "VecGetArray");
    for (std::int64_t i = first; i < last; ++i)
      v[i - first] = p(i);
    check(VecRestoreArray(o.p, &v), "VecRestoreArray");
  }

  check(KSPCreate(PETSC_COMM_WORLD, &o.ksp), "KSPCreate");
  check(KSPSetOperators(o.ksp, o.k, o.k), "KSPSetOperators");
  check(KSPSetType(o.ksp, KSPCG), "KSPSetType");
  // Converged on the true residual |P - K u| <= rtol |P|, not the preconditioned one.
  check(KSPSetNormType(o.ksp, KSP_NORM_UNPRECONDITIONED), "KSPSetNormType");
  PC pc = nullptr;
  check(KSPGetPC(o.ksp, &pc), "KSPGetPC");
  // Smoothed-aggregation multigrid: Trilinos' ML where PETSc has it (243 iterations on a
  // 10 000-block mass, where PETSc's own GAMG takes 609: docs/parallel.md), else GAMG. Both
  // coarsen with the near-null space set above.
#ifdef PETSC_HAVE_ML
  check(PCSetType(pc, PCML), "PCSetType");
#else
  check(PCSetType(pc, PCGAMG), "PCSetType");
#endif
  check(KSPSetTolerances(o.ksp, kPetscRelativeTolerance, 0.0, PETSC_DEFAULT, kPetscIterations),
        "KSPSetTolerances");
  check(KSPSetFromOptions(o.ksp), "KSPSetFromOptions");  // PETSC_OPTIONS may change any of it
  check(KSPSolve(o.ksp, o.p, o.u), "KSPSolve");
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  check(KSPGetConvergedReason(o.ksp, &reason), "KSPGetConvergedReason");
  PetscInt iterations = 0;
  check(KSPGetIterationNumber(o.ksp, &iterations), "KSPGetIterationNumber");
  report.iterations = static_cast<int>(iterations);
  report.method = method(o.ksp, pc);

  // Where the iterations fail (K ill-conditioned: penalty interfaces), MUMPS factorizes K
  // across the processes instead, unless the user chose the method in PETSC_OPTIONS.
  PetscBool chosen = PETSC_FALSE;
  PetscBool pc_chosen = PETSC_FALSE;
  check(PetscOptionsHasName(nullptr, nullptr, "-ksp_type", &chosen), "PetscOptionsHasName");
  check(PetscOptionsHasName(nullptr, nullptr, "-pc_type", &pc_chosen), "PetscOptionsHasName");
  if (reason < 0 && !chosen && !pc_chosen) {
    report.fallback = fmt::format("{} stopped: {} after {} iterations", report.method,
                                  KSPConvergedReasons[reason], report.iterations);
    check(KSPSetType(o.ksp, KSPPREONLY), "KSPSetType");
    check(PCSetType(pc, PCCHOLESKY), "PCSetType");
    check(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS), "PCFactorSetMatSolverType");
    check(KSPSolve(o.ksp, o.p, o.u), "KSPSolve");
    check(KSPGetConvergedReason(o.ksp, &reason), "KSPGetConvergedReason");
    check(KSPGetIterationNumber(o.ksp, &iterations), "KSPGetIterationNumber");
    report.iterations = static_cast<int>(iterations);
    report.method = method(o.ksp, pc);
  }
  // Every process gets the whole u: its order is the model's (contiguous ranges).
  check(VecScatterCreateToAll(o.u, &o.gather, &o.u_all), "VecScatterCreateToAll");
  check(VecScatterBegin(o.gather, o.u, o.u_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterBegin");
  check(VecScatterEnd(o.gather, o.u, o.u_all, INSERT_VALUES, SCATTER_FORWARD), "VecScatterEnd");
  Eigen::VectorXd u(n);
  const PetscScalar* all = nullptr;
  check(VecGetArrayRead(o.u_all, &all), "VecGetArrayRead");
  for (PetscInt i = 0; i < n; ++i)
    u(i) = all[i];
  check(VecRestoreArrayRead(o.u_all, &all), "VecRestoreArrayRead");
  // The residual of the whole u, with the K every process holds: what the solve achieved,
  // whatever norm PETSC_OPTIONS made it stop on.
  const Eigen::VectorXd ku = lower.selfadjointView<Eigen::Lower>() * u;
  report.relative_residual = (p - ku).norm() / std::max(p.norm(), 1e-300);
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
  SparseMatrix k;
  Eigen::VectorXd p;
  assemble_elastic_system(model, k, p, s.timings);
  {
    ScopedTimer t(s.timings, "solve (PETSc)");
    std::vector<Vec2> centroids;
    centroids.reserve(model.blocks.size());
    for (const Block& b : model.blocks)
      centroids.push_back(b.centroid);
    s.u = petsc_solve(k, p, centroids, report);
  }
  {
    ScopedTimer t(s.timings, "evaluate");
    evaluate_fields(model, s);
  }
  return s;
}

}  // namespace bimrock
