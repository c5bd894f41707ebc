#pragma once
/// @file Is every block held? A structure that is not fully supported is reported by naming the
/// blocks that can move freely, never solved (docs/formulation.md).
#include <bimrock/model/model.hpp>

namespace bimrock {

/// Throws ModelError naming the blocks of every group that can move as a rigid body: groups of
/// blocks joined by interfaces with no support, or with supports that leave a rigid motion free
/// (e.g. rollers all parallel, or one support point that lets the group rotate).
void check_supports(const Model& model);

/// Throws ModelError for a stiffness matrix whose factorization failed at global row `row`:
/// the block owning it can move freely (e.g. through joints without shear stiffness).
[[noreturn]] void report_singular_stiffness(const Model& model, long row);

/// "blocks[3] (line 12), blocks[4] (line 13) and 7 more": names of the first few blocks.
std::string name_blocks(const Model& model, const std::vector<int>& blocks);

}  // namespace bimrock
