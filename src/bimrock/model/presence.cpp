#include <bimrock/model/presence.hpp>

#include <bimrock/model/bolts.hpp>
#include <bimrock/model/stage_blocks.hpp>

namespace bimrock {

Presence presence_at(const Model& model, int stage) {
  return {blocks_present(model, stage), springs_present(model, stage)};
}

Presence every_block(const Model& model) {
  return {std::vector<char>(model.blocks.size(), 1),
          std::vector<char>(model.bolt_springs.size(), 0)};
}

}  // namespace bimrock
