#pragma once
/// @file mechanism.csv: how every block takes part in a collapse mechanism (docs/results.md).
#include <filesystem>

#include <bimrock/analysis/mechanism_blocks.hpp>

namespace bimrock {

/// One row per block: its centroid, normalized velocities in the mechanism, the speed of its
/// fastest corner and its state (moves, rotates, stands).
void write_mechanism_csv(const Model& model, const MechanismBlocks& mechanism,
                         const std::filesystem::path& file);

}  // namespace bimrock
