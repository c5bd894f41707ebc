#pragma once
/// @file Where yield is checked (docs/formulation.md): the integration points of every interface
/// whose joint has a strength law (end points for lobatto joints, so that blocks pivot about
/// their corners and topple exactly), and every block with a strength law (on its mean stress).
/// The shared end points of neighbouring pieces of one subdivided joint are merged. And every
/// spring of a bolt (its tensile capacity, and its shear capacity if it has one).
#include <array>
#include <vector>

#include <Eigen/Core>

#include <bimrock/model/model.hpp>
#include <bimrock/model/presence.hpp>

namespace bimrock {

struct YieldPoint {
  enum class Kind { interface, block, bolt };
  Kind kind = Kind::interface;
  /// interface index (the first piece, for a merged point), block index, or bolt spring index
  int owner = 0;
  int block_i = 0;        ///< a bolt spring's block_a
  int block_j = kGround;  ///< interfaces and bolts only (a bolt spring's block_b)
  Vec2 position;          ///< a bolt spring's point a
  Vec2 normal;            ///< interfaces, from i into j; bolts, the axis
  /// t * length share [m^2] for interfaces, t * area [m^3] for blocks, bolts in the model's
  /// thickness [-] for bolt springs
  double weight = 0.0;
  int material = 0;  ///< joint or block material index (none for a bolt spring)
  /// The stress before any displacement (model/initial_stress.hpp): [sigma_n, tau, 0] for an
  /// interface, [sigma_x, sigma_y, tau_xy] for a block [Pa]; a bolt spring's force at its
  /// installation, [pretension, 0, 0] [N].
  Eigen::Vector3d initial = Eigen::Vector3d::Zero();

  [[nodiscard]] bool is_interface() const { return kind == Kind::interface; }
  [[nodiscard]] bool is_block() const { return kind == Kind::block; }
  [[nodiscard]] bool is_bolt() const { return kind == Kind::bolt; }
};

/// Which yield point stands at each interface integration point and each block (-1: none).
struct YieldPointIndex {
  std::vector<std::array<int, 2>> interface_points;  ///< per interface, per integration point
  std::vector<int> block_points;                     ///< per block
  std::vector<int> spring_points;                    ///< per bolt spring
};

/// Flags the blocks a point's rows act on (one for a block point or a support's, else two).
inline void flag_blocks(const YieldPoint& p, std::vector<char>& flags) {
  flags[static_cast<std::size_t>(p.block_i)] = 1;
  if (p.block_j != kGround)
    flags[static_cast<std::size_t>(p.block_j)] = 1;
}

/// Whether a point stands: its blocks are all present (an excavated block's points are not), and
/// a bolt spring's bolt is installed.
inline bool point_present(const YieldPoint& p, const Presence& present) {
  if (p.is_bolt())
    return present.spring(p.owner);
  return present.block(p.block_i) && (p.block_j == kGround || present.block(p.block_j));
}

/// The spring and the bolt of a bolt spring's point.
inline const BoltSpring& spring_of(const Model& model, const YieldPoint& p) {
  return model.bolt_springs[static_cast<std::size_t>(p.owner)];
}
inline const Bolt& bolt_of(const Model& model, const YieldPoint& p) {
  return model.bolts[static_cast<std::size_t>(spring_of(model, p).bolt)];
}

/// @param index if given, filled with where each point stands
std::vector<YieldPoint> make_yield_points(const Model& model, YieldPointIndex* index = nullptr);

/// The number of yield modes (LCP rows) of a yield point: 3 for a joint (slip +, slip -,
/// opening), the number of planes of the block's linearized criterion for a block, 1 for a bolt
/// spring (tension) or 3 if it has a shear capacity (tension, shear +, shear -).
int n_modes(const Model& model, const YieldPoint& p);

}  // namespace bimrock
