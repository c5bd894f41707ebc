#pragma once
/// @file Pictures of the blocks (PNG and SVG with cairo): the model as cut, or a displaced
/// state such as a collapse mechanism, with marked interfaces.
#include <filesystem>
#include <string>
#include <vector>

#include <Eigen/Core>

#include <bimrock/model/model.hpp>

namespace bimrock {

/// How an interface is drawn.
enum class InterfaceMark { none, joint, slipping, opening };

struct BlockPicture {
  std::string title;
  /// Displacement of every block's unknowns (empty: the undisplaced model). Drawn magnified so
  /// that the largest displacement is `displayed_fraction` of the model's size, over the
  /// undisplaced outline in grey.
  Eigen::VectorXd u;
  double displayed_fraction = 0.05;
  /// Per interface (empty: joints drawn thin, continuum interfaces not drawn).
  std::vector<InterfaceMark> marks;
  int width_px = 1000;
};

/// Writes `<stem>.png` and `<stem>.svg`.
void write_block_picture(const Model& model, const BlockPicture& picture,
                         const std::filesystem::path& stem);

}  // namespace bimrock
