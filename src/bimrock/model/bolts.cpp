#include <bimrock/model/bolts.hpp>

#include <stdexcept>
#include <string>

#include <bimrock/model/stage_blocks.hpp>

namespace bimrock {

std::vector<char> springs_present(const Model& model, int stage) {
  if (stage < -1 || stage >= static_cast<int>(model.stages.size()))
    throw std::out_of_range("springs_present: no stage " + std::to_string(stage));
  std::vector<char> present(model.bolt_springs.size(), 0);
  if (stage < 0)
    return present;
  const std::vector<char> blocks = blocks_present(model, stage);
  for (std::size_t k = 0; k < present.size(); ++k) {
    const BoltSpring& s = model.bolt_springs[k];
    present[k] = model.bolts[static_cast<std::size_t>(s.bolt)].stage <= stage &&
                 blocks[static_cast<std::size_t>(s.block_a)] != 0 &&
                 blocks[static_cast<std::size_t>(s.block_b)] != 0;
  }
  return present;
}

}  // namespace bimrock
