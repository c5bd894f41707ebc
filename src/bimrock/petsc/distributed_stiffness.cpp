#include <bimrock/petsc/distributed_stiffness.hpp>

#include <algorithm>
#include <vector>

#include <bimrock/assembly/stiffness_terms.hpp>
#include <bimrock/petsc/petsc_call.hpp>

namespace bimrock {
namespace {

// Adds each term's rows of the owned blocks: a term coupling two processes' blocks is added
// by both, each its own rows, so that no process sends entries to another.
class OwnedRows final : public StiffnessSink {
 public:
  OwnedRows(Mat k, const BlockRange& mine) : k_(k), mine_(mine) {}
  [[nodiscard]] bool wants(int block) const override { return mine_.owns(block); }
  void add(const Mat6& local, int block) override {
    const auto b = static_cast<PetscInt>(block);
    // Row-major, as PETSc reads values; local is symmetric.
    petsc_call(MatSetValuesBlocked(k_, 1, &b, 1, &b, local.data(), ADD_VALUES),
               "MatSetValuesBlocked");
  }
  void add(const Mat12& local, int block_i, int block_j) override {
    const PetscInt columns[2] = {block_i, block_j};
    for (int side = 0; side < 2; ++side) {
      if (!mine_.owns(columns[side]))
        continue;
      const Eigen::Matrix<double, 6, 12, Eigen::RowMajor> rows = local.middleRows<6>(6 * side);
      petsc_call(MatSetValuesBlocked(k_, 1, &columns[side], 2, columns, rows.data(), ADD_VALUES),
                 "MatSetValuesBlocked");
    }
  }

 private:
  Mat k_;
  BlockRange mine_;
};

}  // namespace

BlockRange owned_blocks(std::int64_t blocks, int rank, int ranks) {
  return {blocks * rank / ranks, blocks * (rank + 1) / ranks};
}

Mat assemble_distributed_stiffness(const Model& model, const BlockRange& mine) {
  // The blocks each owned block couples with (across an interface or a bolt's spring): the
  // block rows' non-zero 6 x 6 blocks, on this process's diagonal part or off it.
  std::vector<std::vector<int>> coupled(static_cast<std::size_t>(mine.last - mine.first));
  const auto couple = [&](int a, int b) {
    if (mine.owns(a))
      coupled[static_cast<std::size_t>(a - mine.first)].push_back(b);
    if (mine.owns(b))
      coupled[static_cast<std::size_t>(b - mine.first)].push_back(a);
  };
  for (const Interface& f : model.interfaces)
    if (!f.is_support())
      couple(f.block_i, f.block_j);
  for (const BoltSpring& s : model.bolt_springs)
    couple(s.block_a, s.block_b);
  std::vector<PetscInt> diagonal_part(coupled.size(), 1);  // the block itself
  std::vector<PetscInt> off_part(coupled.size(), 0);
  for (std::size_t b = 0; b < coupled.size(); ++b) {
    std::vector<int>& c = coupled[b];
    std::sort(c.begin(), c.end());
    c.erase(std::unique(c.begin(), c.end()), c.end());
    for (int j : c)
      ++(mine.owns(j) ? diagonal_part[b] : off_part[b]);
    std::vector<int>().swap(c);
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
    OwnedRows rows(k, mine);
    add_stiffness_terms(model, every_block(model), rows);
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
