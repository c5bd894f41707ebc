#include <bimrock/model/presence.hpp>

#include <bimrock/model/bolts.hpp>
#include <bimrock/model/stage_blocks.hpp>

namespace bimrock {

Presence presence_at(const Model& model, int stage) {
  return {blocks_present(model, stage), springs_present(model, stage)};
}

Presence before_bolts(const Model& model, const Presence& before, int stage) {
  Presence dug{blocks_present(model, stage), before.springs};
  for (std::size_t k = 0; k < dug.springs.size(); ++k) {
    const BoltSpring& s = model.bolt_springs[k];
    dug.springs[k] = dug.springs[k] && dug.block(s.block_a) && dug.block(s.block_b);
  }
  return dug;
}

Presence every_block(const Model& model) {
  return {std::vector<char>(model.blocks.size(), 1),
          std::vector<char>(model.bolt_springs.size(), 0)};
}

}  // namespace bimrock
