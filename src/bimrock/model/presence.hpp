#pragma once
/// @file What stands during a stage: its blocks (model/stage_blocks.hpp) and its bolts' springs
/// (model/bolts.hpp). K, the yield points and the loads of a stage are those of what stands.
#include <cstddef>
#include <vector>

#include <bimrock/model/model.hpp>

namespace bimrock {

struct Presence {
  std::vector<char> blocks;   ///< per block: 1 present, 0 absent
  std::vector<char> springs;  ///< per bolt spring: 1 present, 0 absent

  [[nodiscard]] bool block(int b) const { return blocks[static_cast<std::size_t>(b)] != 0; }
  [[nodiscard]] bool spring(int s) const { return springs[static_cast<std::size_t>(s)] != 0; }
  bool operator==(const Presence&) const = default;
};

/// During stage `stage` (after its start); -1: before the first stage. Throws std::out_of_range
/// for another stage.
Presence presence_at(const Model& model, int stage);

/// What stands at stage `stage`'s start once its excavation and installation of blocks are done,
/// before its bolts are installed: its blocks, and the springs of `before` (what stood before
/// it) whose two blocks remain.
Presence before_bolts(const Model& model, const Presence& before, int stage);

/// Every block and no spring: the structure of an elastic analysis.
Presence every_block(const Model& model);

}  // namespace bimrock
