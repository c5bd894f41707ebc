#pragma once
/// @file K spread over the processes of an MPI run (docs/parallel.md). The blocks are numbered
/// in an order that sweeps through the model and divided among the processes in contiguous
/// ranges of it (or by PETSc's graph partitioner, where PETSC_OPTIONS names one); each process
/// assembles only its blocks' rows of K, from the terms that touch them
/// (assembly/stiffness_terms.hpp), into a PETSc matrix. No process holds the whole K.
#include <cstdint>
#include <vector>

#include <petscmat.h>

#include <bimrock/model/model.hpp>
#include <bimrock/model/presence.hpp>

namespace bimrock {

/// A contiguous range [first, last) of block numbers.
struct BlockRange {
  std::int64_t first = 0;
  std::int64_t last = 0;
  [[nodiscard]] bool owns(std::int64_t number) const { return number >= first && number < last; }
  [[nodiscard]] std::int64_t rows() const { return 6 * (last - first); }
};

/// The range of process `rank` of `ranks` over `blocks` numbers: equal counts, in order.
[[nodiscard]] BlockRange owned_blocks(std::int64_t blocks, int rank, int ranks);

/// The blocks' numbering in PETSc's order (block n's unknowns are rows 6n .. 6n + 5 of K there)
/// and this process's range of it.
struct BlockPartition {
  std::vector<std::int64_t> number;  ///< per block of the model, its number
  std::vector<int> block;            ///< per number, the block of the model
  BlockRange mine;                   ///< this process's numbers
};

/// Numbers the blocks and divides them among the processes of PETSC_COMM_WORLD (every process
/// calls it, and gets the same numbering). The numbering follows the model's order, or the
/// reverse Cuthill-McKee order of the block graph where the model's scatters coupled blocks;
/// each process gets a contiguous range of it, equal counts. Where PETSC_OPTIONS sets
/// -mat_partitioning_type (e.g. ptscotch), that partitioner divides the block graph instead,
/// and each process's blocks keep the order above within its range.
[[nodiscard]] BlockPartition partition_blocks(const Model& model);

/// K's rows of this process's blocks (`partition.mine`), in the partition's numbering, as an
/// AIJ matrix of block size 6 (a block's six unknowns) on PETSC_COMM_WORLD, preallocated
/// exactly from the block graph and assembled. Every process calls it; the caller destroys it.
/// K is that of what stands (`present`: the analysis' stages), or of every block.
[[nodiscard]] Mat assemble_distributed_stiffness(const Model& model,
                                                 const BlockPartition& partition,
                                                 const Presence& present);
[[nodiscard]] Mat assemble_distributed_stiffness(const Model& model,
                                                 const BlockPartition& partition);

}  // namespace bimrock
