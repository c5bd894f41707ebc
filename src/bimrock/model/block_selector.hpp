#pragma once
/// @file Choosing blocks (a stage's `excavate` and `install`): those whose centroid lies in a
/// region or a box, those of a block material, or a list of block indices.
#include <vector>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// The blocks `sel` picks, sorted, each once; possibly none. A centroid within the model's
/// tolerance of a region's or a box's boundary counts as inside. Throws InputError naming
/// sel.source for a region that is not an outline (geometry/outline.hpp), a box whose corners
/// are not finite or not lower-left then upper-right, an unknown material, or an index that is
/// not a block of the model.
std::vector<int> select_blocks(const Model& model, const BlockSelector& sel);

}  // namespace bimrock
