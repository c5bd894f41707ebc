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
  /// The phreatic surface to draw (empty: none), across the picture.
  std::vector<Vec2> water_surface;
  /// Per block, whether it is drawn (empty: all): excavated blocks show only as the grey outline
  /// of the undisplaced model.
  std::vector<char> present{};
  /// Per bolt spring, the share of its tensile capacity its axial force uses (NaN: not standing;
  /// empty: no bolts drawn). A bolt is a thin line from its head to its far end; its springs are
  /// drawn over it, green when slack, red at their capacity (an anchored bolt's one spring as a
  /// line, a grouted bolt's, at the joints it crosses, as dots).
  std::vector<double> bolt_use{};
};

/// The length of a picture's scale bar for a drawing `width` wide [m]: the largest 1, 2 or 5
/// times a power of ten that is at most a fifth of it.
[[nodiscard]] double scale_bar_length(double width);

/// How many times the displacements `u` are magnified in a picture of the model: so that the
/// largest displacement of a block corner is `fraction` of `size` [m] (0: no displacement).
/// `present` (per block; empty: all) limits it to those blocks.
[[nodiscard]] double displacement_magnification(const Model& model, const Eigen::VectorXd& u,
                                                double fraction, double size,
                                                const std::vector<char>& present = {});

/// Writes `<stem>.png` and `<stem>.svg`: the blocks coloured by material (a legend names them
/// where there are several), the magnification of the displacements, and a scale bar.
void write_block_picture(const Model& model, const BlockPicture& picture,
                         const std::filesystem::path& stem);

}  // namespace bimrock
