// K assembled by rows across the processes (petsc/distributed_stiffness.hpp) against K assembled
// whole on one process (assembly/global_system.hpp, the CHOLMOD path's): each process must hold
// exactly the rows of its own blocks, with the same non-zeros and values. The same binary runs
// under `mpirun -n 2` (tests/CMakeLists.txt), where half of the blocks' terms straddle no
// process and the interfaces between the two halves are added by both, each its own rows.
// (PETSc is initialized for the whole program by elastic_solve_test.cpp's environment.)
#include <algorithm>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/petsc/distributed_stiffness.hpp>
#include <bimrock/reference/reference_cases.hpp>

namespace bimrock {
namespace {

void expect_rows_of_whole_k(const Model& model, const std::string& name) {
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const BlockRange mine = owned_blocks(model.n_blocks(), rank, ranks);
  Mat k = assemble_distributed_stiffness(model, mine);
  PetscInt first = 0;
  PetscInt last = 0;
  ASSERT_EQ(MatGetOwnershipRange(k, &first, &last), 0);
  EXPECT_EQ(first, 6 * mine.first) << name;
  EXPECT_EQ(last, 6 * mine.last) << name;

  // K is symmetric: column r of the whole K is its row r.
  const SparseMatrix whole = full_from_lower(assemble_stiffness_lower(model));
  const double scale = whole.coeffs().cwiseAbs().maxCoeff();
  int wrong_patterns = 0;  // rows with an entry the whole K has not
  double worst = 0.0;
  for (PetscInt r = first; r < last; ++r) {
    PetscInt count = 0;
    const PetscInt* columns = nullptr;
    const PetscScalar* values = nullptr;
    ASSERT_EQ(MatGetRow(k, r, &count, &columns, &values), 0);
    // Both rows sorted by column: walk them together. The whole K keeps explicit zeros (its
    // pattern holds every bolt spring, standing or not), PETSc's compressed rows do not.
    PetscInt e = 0;
    for (SparseMatrix::InnerIterator expected(whole, r); expected; ++expected) {
      double value = 0.0;
      if (e < count && columns[e] == expected.row())
        value = values[e++];
      worst = std::max(worst, std::abs(value - expected.value()) / scale);
    }
    if (e < count)
      ++wrong_patterns;  // an entry outside the whole K's pattern
    ASSERT_EQ(MatRestoreRow(k, r, &count, &columns, &values), 0);
  }
  MatDestroy(&k);
  EXPECT_EQ(wrong_patterns, 0) << name;
  EXPECT_LT(worst, 1e-14) << name;
}

Model example_model(const char* name) {
  const std::filesystem::path file = std::filesystem::path(BIMROCK_SOURCE_DIR) / "examples" / name;
  return build_model(read_case_file(file.string()).spec);
}

TEST(DistributedStiffness, EachProcessHoldsExactlyTheRowsOfItsBlocks) {
  // Joints; penalty interfaces and supports; bolts' springs (every one counted as standing).
  for (const char* name : {"jointed_rock_mass/case3_biaxial.yaml", "rock_slope/case.yaml",
                           "tunnel_excavation/bolted.yaml"})
    expect_rows_of_whole_k(example_model(name), name);
  expect_rows_of_whole_k(build_model(brick_mass_case(3000)), "brick mass");
}

TEST(DistributedStiffness, RangesSplitTheBlocksInOrder) {
  for (const int ranks : {1, 2, 3, 7}) {
    std::int64_t next = 0;
    for (int rank = 0; rank < ranks; ++rank) {
      const BlockRange r = owned_blocks(100, rank, ranks);
      EXPECT_EQ(r.first, next);
      EXPECT_GE(r.last - r.first, 100 / ranks);
      EXPECT_LE(r.last - r.first, 100 / ranks + 1);
      next = r.last;
    }
    EXPECT_EQ(next, 100);
  }
}

}  // namespace
}  // namespace bimrock
