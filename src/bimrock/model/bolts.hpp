#pragma once
/// @file Rock bolts and anchors: the case's bolts resolved into springs between blocks
/// (docs/case-file.md, "Bolts"; docs/formulation.md, "Bolts"). A bolt's line from its head to
/// its far end passes through the blocks present at its installation, one after another; an
/// anchored bolt joins the first (at its head) to the last (at its far end), a grouted bolt each
/// block to the next, at the point where the line crosses from one into the other.
#include <vector>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// Resolves `bolts` into model.bolts and model.bolt_springs (model.stages resolved first, with
/// their excavated and installed blocks). Throws InputError naming the bolt's item (the line of
/// the offending key) when the case has no stages; `install` names no stage; a number is not
/// finite or out of its range (stiffnesses and capacities > 0, pretension in [0, capacity),
/// spacing > 0); a grouted bolt is pretensioned; a shear capacity is given without a shear
/// stiffness; the head and far end coincide; the line leaves the blocks present at its
/// installation (it must run inside them from head to far end), runs along a joint, or stays in
/// one block (it would join nothing).
void add_bolts(Model& model, const std::vector<BoltSpec>& bolts);

/// The springs standing during stage `stage` (after its start: its excavation and installation):
/// 1 for those of a bolt installed at or before it whose two blocks are present, else 0, by
/// spring index. stage = -1: before the first stage, when no bolt stands. Throws
/// std::out_of_range for another stage.
std::vector<char> springs_present(const Model& model, int stage);

}  // namespace bimrock
