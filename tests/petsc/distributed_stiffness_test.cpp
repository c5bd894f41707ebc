// K assembled by rows across the processes (petsc/distributed_stiffness.hpp) against K assembled
// whole on one process (assembly/global_system.hpp, the CHOLMOD path's): each process must hold
// exactly the rows of its own blocks, in the partition's numbering, with the same non-zeros and
// values. The same binary runs under `mpirun -n 2` (tests/CMakeLists.txt), where the
// partitioner divides the blocks and the interfaces between the two parts are added by both
// processes, each its own rows.
// (PETSc is initialized for the whole program by elastic_solve_test.cpp's environment.)
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/assembly/global_system.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/petsc/distributed_stiffness.hpp>
#include <bimrock/petsc/elastic_solve.hpp>
#include <bimrock/reference/reference_cases.hpp>

namespace bimrock {
namespace {

void expect_rows_of_whole_k(const Model& model, const std::string& name) {
  int ranks = 1;
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const BlockPartition partition = partition_blocks(model);
  const BlockRange& mine = partition.mine;
  // The numbering is a permutation of the blocks, the same on every process, and the
  // partitioner's parts are of near-equal size.
  std::vector<char> seen(static_cast<std::size_t>(model.n_blocks()), 0);
  for (std::int64_t n : partition.number)
    seen[static_cast<std::size_t>(n)] = 1;
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), model.n_blocks()) << name;
  for (std::size_t b = 0; b < partition.number.size(); ++b)
    ASSERT_EQ(partition.block[static_cast<std::size_t>(partition.number[b])], static_cast<int>(b));
  EXPECT_LE(static_cast<double>(mine.last - mine.first), 1.1 * model.n_blocks() / ranks + 1)
      << name;

  Mat k = assemble_distributed_stiffness(model, partition);
  PetscInt first = 0;
  PetscInt last = 0;
  ASSERT_EQ(MatGetOwnershipRange(k, &first, &last), 0);
  EXPECT_EQ(first, 6 * mine.first) << name;
  EXPECT_EQ(last, 6 * mine.last) << name;

  // Row r of PETSc's K is row `unknown(r)` of the whole K, its columns too. K is symmetric:
  // column r of the whole K is its row r.
  const auto unknown = [&](PetscInt r) {
    return 6 * static_cast<std::int64_t>(partition.block[static_cast<std::size_t>(r / 6)]) + r % 6;
  };
  const SparseMatrix whole = full_from_lower(assemble_stiffness_lower(model));
  const double scale = whole.coeffs().cwiseAbs().maxCoeff();
  int wrong_patterns = 0;  // rows with an entry the whole K has not
  double worst = 0.0;
  for (PetscInt r = first; r < last; ++r) {
    PetscInt count = 0;
    const PetscInt* columns = nullptr;
    const PetscScalar* values = nullptr;
    ASSERT_EQ(MatGetRow(k, r, &count, &columns, &values), 0);
    std::map<std::int64_t, double> row;
    for (PetscInt e = 0; e < count; ++e)
      row[unknown(columns[e])] = values[e];
    ASSERT_EQ(MatRestoreRow(k, r, &count, &columns, &values), 0);
    // The whole K keeps explicit zeros (its pattern holds every bolt spring, standing or not),
    // PETSc's compressed rows do not.
    for (SparseMatrix::InnerIterator expected(whole, unknown(r)); expected; ++expected) {
      const auto it = row.find(expected.row());
      worst = std::max(worst,
                       std::abs((it == row.end() ? 0.0 : it->second) - expected.value()) / scale);
      if (it != row.end())
        row.erase(it);
    }
    if (!row.empty())
      ++wrong_patterns;
  }
  MatDestroy(&k);
  EXPECT_EQ(wrong_patterns, 0) << name;
  EXPECT_LT(worst, 1e-14) << name;
}

Model example_model(const char* name) {
  const std::filesystem::path file = std::filesystem::path(BIMROCK_SOURCE_DIR) / "examples" / name;
  return build_model(read_case_file(file.string()).spec);
}

// A brick mass whose blocks are listed in a random order.
Model shuffled_brick_mass(int blocks) {
  CaseSpec spec = brick_mass_case(blocks);
  std::mt19937 random(7);
  for (std::size_t i = spec.blocks.size() - 1; i > 0; --i) {
    std::uniform_int_distribution<std::size_t> pick(0, i);
    std::swap(spec.blocks[i], spec.blocks[pick(random)]);
  }
  return build_model(spec);
}

TEST(DistributedStiffness, EachProcessHoldsExactlyTheRowsOfItsBlocks) {
  // Joints; penalty interfaces and supports; bolts' springs (every one counted as standing); a
  // model renumbered in sweeps. With the default ranges of the numbering, and with PT-Scotch's
  // parts.
  for (const char* partitioner : {"", "ptscotch"}) {
    if (*partitioner != '\0') {
      ASSERT_EQ(PetscOptionsSetValue(nullptr, "-mat_partitioning_type", partitioner), 0);
    }
    for (const char* name : {"jointed_rock_mass/case3_biaxial.yaml", "rock_slope/case.yaml",
                             "tunnel_excavation/bolted.yaml"})
      expect_rows_of_whole_k(example_model(name), name + std::string(" ") + partitioner);
    expect_rows_of_whole_k(build_model(brick_mass_case(3000)), "brick mass");
    expect_rows_of_whole_k(shuffled_brick_mass(3000), "shuffled brick mass");
    ASSERT_EQ(PetscOptionsClearValue(nullptr, "-mat_partitioning_type"), 0);
  }
}

// The multigrid aggregates the blocks in the order of their numbers: a model whose blocks are
// listed at random is renumbered in sweeps (reverse Cuthill-McKee) and converges nearly as fast
// as the same mass listed in order (without the renumbering: 63 iterations against 28 at
// 10^5 blocks). Its displacements are CHOLMOD's, as any model's.
TEST(DistributedStiffness, AModelListedAtRandomIsRenumberedInSweeps) {
  PetscSolveReport ordered;
  (void)solve_elastic_with_petsc(build_model(brick_mass_case(3000)), ordered);
  const Model model = shuffled_brick_mass(3000);
  PetscSolveReport shuffled;
  const ElasticSolution petsc = solve_elastic_with_petsc(model, shuffled);
  std::printf("brick mass: %d iterations in order, %d listed at random\n", ordered.iterations,
              shuffled.iterations);
  EXPECT_LE(shuffled.iterations, 1.3 * ordered.iterations);
  const ElasticSolution direct = solve_elastic(model);
  EXPECT_LT((petsc.u - direct.u).cwiseAbs().maxCoeff(), 1e-8 * direct.u.cwiseAbs().maxCoeff());
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
