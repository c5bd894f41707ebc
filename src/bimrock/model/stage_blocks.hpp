#pragma once
/// @file Which blocks take part in each stage. A stage's `excavate` removes blocks at its start,
/// its `install` adds blocks that were absent until then (docs/case-file.md, "Excavation and
/// installation"): a block some stage installs is absent from the start until that stage.
#include <vector>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// Resolves the `excavate` and `install` of each stage spec into model.stages[k].excavated and
/// .installed, and copies its `release`. model.stages holds the stages of `stages`, in order, with
/// their loads resolved. Throws InputError naming the stage's item when a selector picks no block;
/// a stage excavates a block absent at its start (already excavated, or installed only later),
/// installs a block installed by an earlier stage, excavates and installs the same block, or
/// excavates every block present; `release` is not in (0, 1], or below 1 while no stage up to
/// this one excavates; a stage's point load, traction or displacement-controlled monitor lies on
/// a block absent during the stage. Monitors may follow any block.
void resolve_stage_blocks(Model& model, const std::vector<StageSpec>& stages);

/// Whether a block stands before the first stage: all but those some stage installs (`installed`
/// of each stage sorted, as resolve_stage_blocks() leaves it). One block's answer, without the
/// vector blocks_present(model, -1) makes.
bool present_at_start(const Model& model, int block);

/// The blocks present during stage `stage` (after its own excavation and installation): 1 for
/// present, 0 for absent, by block index. stage = -1: before the first stage, when every block is
/// present except those some stage installs. Throws std::out_of_range for another stage.
std::vector<char> blocks_present(const Model& model, int stage);

}  // namespace bimrock
