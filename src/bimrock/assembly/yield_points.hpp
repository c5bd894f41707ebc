#pragma once
/// @file Where yield is checked (docs/formulation.md): the integration points of every interface
/// whose joint has a strength law (end points for lobatto joints, so that blocks pivot about
/// their corners and topple exactly), and every block with a strength law (on its mean stress).
/// The shared end points of neighbouring pieces of one subdivided joint are merged.
#include <array>
#include <vector>

#include <Eigen/Core>

#include <bimrock/model/model.hpp>

namespace bimrock {

struct YieldPoint {
  enum class Kind { interface, block };
  Kind kind = Kind::interface;
  int owner = 0;  ///< interface index (the first piece, for a merged point) or block index
  int block_i = 0;
  int block_j = kGround;  ///< interfaces only
  Vec2 position;
  Vec2 normal;          ///< interfaces only, from i into j
  double weight = 0.0;  ///< t * length share [m^2] for interfaces, t * area [m^3] for blocks
  int material = 0;     ///< joint or block material index
  /// The stress before any displacement (model/initial_stress.hpp): [sigma_n, tau, 0] for an
  /// interface, [sigma_x, sigma_y, tau_xy] for a block [Pa].
  Eigen::Vector3d initial = Eigen::Vector3d::Zero();

  [[nodiscard]] bool is_interface() const { return kind == Kind::interface; }
};

/// Which yield point stands at each interface integration point and each block (-1: none).
struct YieldPointIndex {
  std::vector<std::array<int, 2>> interface_points;  ///< per interface, per integration point
  std::vector<int> block_points;                     ///< per block
};

/// Flags the blocks a point's rows act on (one for a block point or a support's, else two).
inline void flag_blocks(const YieldPoint& p, std::vector<char>& flags) {
  flags[static_cast<std::size_t>(p.block_i)] = 1;
  if (p.block_j != kGround)
    flags[static_cast<std::size_t>(p.block_j)] = 1;
}

/// Whether a point's blocks are all present (per block; an excavated block's points are not).
inline bool point_present(const YieldPoint& p, const std::vector<char>& present) {
  return present[static_cast<std::size_t>(p.block_i)] != 0 &&
         (p.block_j == kGround || present[static_cast<std::size_t>(p.block_j)] != 0);
}

/// @param index if given, filled with where each point stands
std::vector<YieldPoint> make_yield_points(const Model& model, YieldPointIndex* index = nullptr);

/// The number of yield modes (LCP rows) of a yield point: 3 for a joint (slip +, slip -,
/// opening), the number of planes of the block's linearized criterion for a block.
int n_modes(const Model& model, const YieldPoint& p);

}  // namespace bimrock
