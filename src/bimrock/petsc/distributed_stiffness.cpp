#include <bimrock/petsc/distributed_stiffness.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <numeric>
#include <vector>

#include <bimrock/assembly/stiffness_terms.hpp>
#include <bimrock/petsc/owned.hpp>
#include <bimrock/petsc/petsc_call.hpp>

namespace bimrock {
namespace {

// Per block of `range` (numbers of the partition), the numbers of the blocks it couples with
// across an interface or a bolt's spring, sorted, without itself.
std::vector<std::vector<std::int64_t>> coupled_blocks(const Model& model,
                                                      const std::vector<std::int64_t>& number,
                                                      const BlockRange& range) {
  std::vector<std::vector<std::int64_t>> coupled(
      static_cast<std::size_t>(range.last - range.first));
  const auto couple = [&](int a, int b) {
    const std::int64_t na = number[static_cast<std::size_t>(a)];
    const std::int64_t nb = number[static_cast<std::size_t>(b)];
    if (range.owns(na))
      coupled[static_cast<std::size_t>(na - range.first)].push_back(nb);
    if (range.owns(nb))
      coupled[static_cast<std::size_t>(nb - range.first)].push_back(na);
  };
  for (const Interface& f : model.interfaces)
    if (!f.is_support())
      couple(f.block_i, f.block_j);
  for (const BoltSpring& s : model.bolt_springs)
    couple(s.block_a, s.block_b);
  for (std::vector<std::int64_t>& c : coupled) {
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
  }
  return coupled;
}

// Adds each term's rows of the owned blocks: a term coupling two processes' blocks is added
// by both, each its own rows, so that no process sends entries to another.
class OwnedRows final : public StiffnessSink {
 public:
  OwnedRows(Mat k, const BlockPartition& partition) : k_(k), partition_(partition) {}
  [[nodiscard]] bool wants(int block) const override { return partition_.mine.owns(number(block)); }
  void add(const Mat6& local, int block) override {
    const PetscInt b = number(block);
    // Row-major, as PETSc reads values; local is symmetric.
    petsc_call(MatSetValuesBlocked(k_, 1, &b, 1, &b, local.data(), ADD_VALUES),
               "MatSetValuesBlocked");
  }
  void add(const Mat12& local, int block_i, int block_j) override {
    const PetscInt columns[2] = {number(block_i), number(block_j)};
    for (int side = 0; side < 2; ++side) {
      if (!partition_.mine.owns(columns[side]))
        continue;
      const Eigen::Matrix<double, 6, 12, Eigen::RowMajor> rows = local.middleRows<6>(6 * side);
      petsc_call(MatSetValuesBlocked(k_, 1, &columns[side], 2, columns, rows.data(), ADD_VALUES),
                 "MatSetValuesBlocked");
    }
  }

 private:
  [[nodiscard]] PetscInt number(int block) const {
    return static_cast<PetscInt>(partition_.number[static_cast<std::size_t>(block)]);
  }
  Mat k_;
  const BlockPartition& partition_;
};

// The destination process of each block of `range` (contiguous in the model's order: the
// graph's initial distribution), from the partitioner PETSC_OPTIONS names, on the block graph.
std::vector<PetscInt> destinations(const Model& model, const BlockRange& range) {
  std::vector<std::int64_t> identity(static_cast<std::size_t>(model.n_blocks()));
  std::iota(identity.begin(), identity.end(), 0);
  const std::vector<std::vector<std::int64_t>> coupled = coupled_blocks(model, identity, range);
  // The adjacency in compressed rows, in PETSc's memory: the graph matrix takes it over.
  PetscInt* start = nullptr;
  PetscInt* columns = nullptr;
  std::size_t edges = 0;
  for (const auto& c : coupled)
    edges += c.size();
  petsc_call(PetscMalloc1(coupled.size() + 1, &start), "PetscMalloc1");
  petsc_call(PetscMalloc1(std::max<std::size_t>(edges, 1), &columns), "PetscMalloc1");
  start[0] = 0;
  for (std::size_t b = 0; b < coupled.size(); ++b) {
    std::copy(coupled[b].begin(), coupled[b].end(), columns + start[b]);
    start[b + 1] = start[b] + static_cast<PetscInt>(coupled[b].size());
  }
  Owned<Mat, MatDestroy> graph;
  Owned<MatPartitioning, MatPartitioningDestroy> partitioner;
  Owned<IS, ISDestroy> destination;
  const auto n = static_cast<PetscInt>(model.n_blocks());
  petsc_call(MatCreateMPIAdj(PETSC_COMM_WORLD, static_cast<PetscInt>(coupled.size()), n, start,
                             columns, nullptr, graph.out()),
             "MatCreateMPIAdj");
  petsc_call(MatPartitioningCreate(PETSC_COMM_WORLD, partitioner.out()), "MatPartitioningCreate");
  petsc_call(MatPartitioningSetAdjacency(partitioner.get(), graph.get()),
             "MatPartitioningSetAdjacency");
  petsc_call(MatPartitioningSetFromOptions(partitioner.get()), "MatPartitioningSetFromOptions");
  petsc_call(MatPartitioningApply(partitioner.get(), destination.out()), "MatPartitioningApply");
  const PetscInt* d = nullptr;
  petsc_call(ISGetIndices(destination.get(), &d), "ISGetIndices");
  std::vector<PetscInt> out(d, d + coupled.size());
  petsc_call(ISRestoreIndices(destination.get(), &d), "ISRestoreIndices");
  return out;
}

// The mean distance in a numbering (`position` of each block) between coupled blocks.
double mean_span(const std::vector<std::vector<std::int64_t>>& coupled,
                 const std::vector<std::int64_t>& position) {
  double sum = 0.0;
  std::int64_t count = 0;
  for (std::size_t b = 0; b < coupled.size(); ++b)
    for (std::int64_t c : coupled[b]) {
      sum += static_cast<double>(std::abs(position[b] - position[static_cast<std::size_t>(c)]));
      ++count;
    }
  return count == 0 ? 0.0 : sum / static_cast<double>(count);
}

// The order the blocks are numbered in (per position, a block): the model's, unless it puts
// coupled blocks more than twice as far apart, on average, as the reverse Cuthill-McKee order of
// the block graph (PETSc's), which then replaces it. The multigrid aggregates blocks in the
// order of their numbers, and an order that sweeps through the model makes compact aggregates:
// a 10^5-block mass takes 28 iterations in the order its blocks were generated, 39 in
// Cuthill-McKee's, and 63 with its blocks listed at random (47 reordered by Cuthill-McKee).
std::vector<int> sweep_order(const Model& model) {
  std::vector<std::int64_t> position(static_cast<std::size_t>(model.n_blocks()));
  std::iota(position.begin(), position.end(), 0);
  const std::vector<std::vector<std::int64_t>> coupled =
      coupled_blocks(model, position, {0, model.n_blocks()});
  std::vector<PetscInt> start(coupled.size() + 1, 0);
  std::vector<PetscInt> columns;
  for (std::size_t b = 0; b < coupled.size(); ++b) {
    columns.insert(columns.end(), coupled[b].begin(), coupled[b].end());
    start[b + 1] = static_cast<PetscInt>(columns.size());
  }
  const std::vector<PetscScalar> ones(std::max<std::size_t>(columns.size(), 1), 1.0);
  Owned<Mat, MatDestroy> graph;
  Owned<IS, ISDestroy> rows;
  Owned<IS, ISDestroy> cols;
  const auto n = static_cast<PetscInt>(coupled.size());
  petsc_call(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, n, n, start.data(), columns.data(),
                                       const_cast<PetscScalar*>(ones.data()), graph.out()),
             "MatCreateSeqAIJWithArrays");
  petsc_call(MatGetOrdering(graph.get(), MATORDERINGRCM, rows.out(), cols.out()), "MatGetOrdering");
  const PetscInt* order = nullptr;
  petsc_call(ISGetIndices(rows.get(), &order), "ISGetIndices");
  std::vector<int> rcm(order, order + n);
  petsc_call(ISRestoreIndices(rows.get(), &order), "ISRestoreIndices");
  const double model_span = mean_span(coupled, position);
  for (std::size_t k = 0; k < rcm.size(); ++k)
    position[static_cast<std::size_t>(rcm[k])] = static_cast<std::int64_t>(k);
  if (2.0 * mean_span(coupled, position) < model_span)
    return rcm;
  std::iota(rcm.begin(), rcm.end(), 0);
  return rcm;
}

}  // namespace

BlockRange owned_blocks(std::int64_t blocks, int rank, int ranks) {
  return {blocks * rank / ranks, blocks * (rank + 1) / ranks};
}

BlockPartition partition_blocks(const Model& model) {
  int rank = 0;
  int ranks = 1;
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  MPI_Comm_size(PETSC_COMM_WORLD, &ranks);
  const auto blocks = static_cast<std::size_t>(model.n_blocks());
  const std::vector<int> order = sweep_order(model);
  // Every process learns every block's destination: by default, contiguous ranges of the order
  // (ML aggregates within each process, and these strips converge fastest: 26 iterations on a
  // 10^5-block mass on two processes, where PT-Scotch's parts take 41); PETSc's partitioner where
  // PETSC_OPTIONS names one (-mat_partitioning_type ptscotch).
  std::vector<PetscInt> destination(blocks, 0);
  PetscBool chosen = PETSC_FALSE;
  petsc_call(PetscOptionsHasName(nullptr, nullptr, "-mat_partitioning_type", &chosen),
             "PetscOptionsHasName");
  if (ranks > 1 && chosen) {
    const std::vector<PetscInt> mine =
        destinations(model, owned_blocks(model.n_blocks(), rank, ranks));
    std::vector<int> counts(static_cast<std::size_t>(ranks));
    std::vector<int> offsets(static_cast<std::size_t>(ranks));
    for (int r = 0; r < ranks; ++r) {
      const BlockRange range = owned_blocks(model.n_blocks(), r, ranks);
      counts[static_cast<std::size_t>(r)] = static_cast<int>(range.last - range.first);
      offsets[static_cast<std::size_t>(r)] = static_cast<int>(range.first);
    }
    MPI_Allgatherv(mine.data(), static_cast<int>(mine.size()), MPIU_INT, destination.data(),
                   counts.data(), offsets.data(), MPIU_INT, PETSC_COMM_WORLD);
  } else {
    for (int r = 0; r < ranks; ++r) {
      const BlockRange range = owned_blocks(model.n_blocks(), r, ranks);
      for (std::int64_t k = range.first; k < range.last; ++k)
        destination[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = r;
    }
  }
  // The blocks numbered by destination, and within a destination in the order above.
  BlockPartition p;
  p.block = order;
  std::stable_sort(p.block.begin(), p.block.end(), [&](int a, int b) {
    return destination[static_cast<std::size_t>(a)] < destination[static_cast<std::size_t>(b)];
  });
  p.number.resize(blocks);
  for (std::size_t n = 0; n < blocks; ++n)
    p.number[static_cast<std::size_t>(p.block[n])] = static_cast<std::int64_t>(n);
  std::int64_t before = 0;
  std::int64_t own = 0;
  for (PetscInt d : destination) {
    before += d < rank;
    own += d == rank;
  }
  p.mine = {before, before + own};
  return p;
}

Mat assemble_distributed_stiffness(const Model& model, const BlockPartition& partition) {
  return assemble_distributed_stiffness(model, partition, every_block(model));
}

Mat assemble_distributed_stiffness(const Model& model, const BlockPartition& partition,
                                   const Presence& present) {
  // The block rows' non-zero 6 x 6 blocks, on this process's diagonal part or off it.
  const BlockRange& mine = partition.mine;
  std::vector<PetscInt> diagonal_part(static_cast<std::size_t>(mine.last - mine.first), 1);
  std::vector<PetscInt> off_part(diagonal_part.size(), 0);
  {
    const std::vector<std::vector<std::int64_t>> coupled =
        coupled_blocks(model, partition.number, mine);
    for (std::size_t b = 0; b < coupled.size(); ++b)
      for (std::int64_t j : coupled[b])
        ++(mine.owns(j) ? diagonal_part[b] : off_part[b]);
  }

  Mat k = nullptr;
  const auto m = static_cast<PetscInt>(mine.rows());
  const auto n = static_cast<PetscInt>(model.n_dofs());
  petsc_call(MatCreate(PETSC_COMM_WORLD, &k), "MatCreate");
  try {
    petsc_call(MatSetSizes(k, m, m, n, n), "MatSetSizes");
    petsc_call(MatSetType(k, MATAIJ), "MatSetType");
    petsc_call(MatSetBlockSize(k, 6), "MatSetBlockSize");
    petsc_call(
        MatXAIJSetPreallocation(k, 6, diagonal_part.data(), off_part.data(), nullptr, nullptr),
        "MatXAIJSetPreallocation");
    // Each process adds only its own rows; an entry outside the preallocation is a bug.
    petsc_call(MatSetOption(k, MAT_NO_OFF_PROC_ENTRIES, PETSC_TRUE), "MatSetOption");
    petsc_call(MatSetOption(k, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE), "MatSetOption");
    OwnedRows rows(k, partition);
    add_stiffness_terms(model, present, rows);
    petsc_call(MatAssemblyBegin(k, MAT_FINAL_ASSEMBLY), "MatAssemblyBegin");
    petsc_call(MatAssemblyEnd(k, MAT_FINAL_ASSEMBLY), "MatAssemblyEnd");
    petsc_call(MatSetOption(k, MAT_SPD, PETSC_TRUE), "MatSetOption(MAT_SPD)");
  } catch (...) {
    MatDestroy(&k);
    throw;
  }
  return k;
}

}  // namespace bimrock
