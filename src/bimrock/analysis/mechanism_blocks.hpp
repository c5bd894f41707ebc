#pragma once
/// @file How each block takes part in a collapse mechanism, as an engineer reads it: its
/// velocities in the mechanism (the block's 6 unknowns of Collapse::direction, normalized so
/// that the fastest corner of any block moves at 1) and whether it moves, rotates or stands.
#include <vector>

#include <Eigen/Core>

#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/model/model.hpp>

namespace bimrock {

enum class BlockMotion {
  moves,    ///< translates (possibly with some rotation about a distant point)
  rotates,  ///< rotation dominant: the instantaneous centre lies on or near the block
  stands,   ///< negligible motion against the mechanism's fastest corner
};

[[nodiscard]] const char* block_motion_name(BlockMotion m);

/// A block stands when its fastest corner moves slower than this fraction of the mechanism's
/// fastest corner.
inline constexpr double kStandingFraction = 1e-3;

/// A moving block rotates when its instantaneous centre of rotation lies within this many
/// times R of its centroid (R: the distance from the centroid to its farthest corner), that is
/// when |(u0, v0)| <= kRotationReach |theta| R. A block toppling about one of its corners has
/// its centre at most R away; a block sliding with a little rotation, far away.
inline constexpr double kRotationReach = 2.0;

/// The largest speed |Q(x, y) d| over the corners of a block of centroid c (the speed is
/// affine in (x, y), so its largest over a convex polygon is at a corner).
[[nodiscard]] double fastest_corner_speed(const Vec6& d, const Vec2& c,
                                          const std::vector<Vec2>& corners);

/// The state of a block with (normalized) velocities d, whose fastest corner moves at `speed`,
/// where the mechanism's fastest corner moves at `largest`.
[[nodiscard]] BlockMotion classify_block_motion(const Vec6& d, const Vec2& c,
                                                const std::vector<Vec2>& corners, double speed,
                                                double largest);

struct MechanismBlock {
  Vec6 velocity = Vec6::Zero();  ///< [u0, v0, theta, eps_x, eps_y, gamma_xy], normalized
  double speed = 0.0;            ///< of its fastest corner, normalized (the largest is 1)
  BlockMotion motion = BlockMotion::stands;
};

struct MechanismBlocks {
  /// What the direction's entries were divided by: its fastest corner speed (0: no motion).
  double scale = 0.0;
  std::vector<MechanismBlock> blocks;
};

/// Every block's part in the mechanism `direction` (all block unknowns; an empty or all-zero
/// direction leaves every block standing).
[[nodiscard]] MechanismBlocks mechanism_blocks(const Model& model,
                                               const Eigen::VectorXd& direction);

/// The normalized velocities of every block, 6 per block (as the model's unknowns).
[[nodiscard]] Eigen::VectorXd stacked_velocities(const MechanismBlocks& m);

}  // namespace bimrock
