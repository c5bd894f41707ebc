#pragma once
/// @file K spread over the processes of an MPI run (docs/parallel.md): each process owns a
/// contiguous range of blocks and assembles only their rows of K, from the terms that touch
/// them (assembly/stiffness_terms.hpp), into a PETSc matrix. No process holds the whole K.
#include <cstdint>

#include <petscmat.h>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// The blocks a process owns: [first, last) of the model's order, equal counts.
struct BlockRange {
  std::int64_t first = 0;
  std::int64_t last = 0;
  [[nodiscard]] bool owns(std::int64_t block) const { return block >= first && block < last; }
  [[nodiscard]] std::int64_t rows() const { return 6 * (last - first); }
};

/// The range of process `rank` of `ranks` over `blocks` blocks.
[[nodiscard]] BlockRange owned_blocks(std::int64_t blocks, int rank, int ranks);

/// K's rows of the blocks of `mine` on this process (every process calls it with its own
/// range), as an AIJ matrix of block size 6 (a block's six unknowns) on PETSC_COMM_WORLD,
/// preallocated exactly from the block graph and assembled. The caller destroys it.
[[nodiscard]] Mat assemble_distributed_stiffness(const Model& model, const BlockRange& mine);

}  // namespace bimrock
