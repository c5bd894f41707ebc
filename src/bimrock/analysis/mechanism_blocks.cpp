#include <bimrock/analysis/mechanism_blocks.hpp>

#include <algorithm>
#include <cmath>

namespace bimrock {

const char* block_motion_name(BlockMotion m) {
  switch (m) {
    case BlockMotion::moves:
      return "moves";
    case BlockMotion::rotates:
      return "rotates";
    case BlockMotion::stands:
      return "stands";
  }
  return "?";
}

double fastest_corner_speed(const Vec6& d, const Vec2& c, const std::vector<Vec2>& corners) {
  double fastest = 0.0;
  for (const Vec2& p : corners)
    fastest = std::max(fastest, (block_Q(c, p) * d).norm());
  return fastest;
}

BlockMotion classify_block_motion(const Vec6& d, const Vec2& c, const std::vector<Vec2>& corners,
                                  double speed, double largest) {
  if (!(largest > 0.0) || speed < kStandingFraction * largest)
    return BlockMotion::stands;
  double reach = 0.0;
  for (const Vec2& p : corners)
    reach = std::max(reach, (p - c).norm());
  const double translation = std::hypot(d(0), d(1));
  return translation <= kRotationReach * std::abs(d(2)) * reach ? BlockMotion::rotates
                                                                : BlockMotion::moves;
}

MechanismBlocks mechanism_blocks(const Model& model, const Eigen::VectorXd& direction) {
  MechanismBlocks m;
  m.blocks.resize(static_cast<std::size_t>(model.n_blocks()));
  if (direction.size() != model.n_dofs())
    return m;
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    const Block& block = model.blocks[b];
    m.blocks[b].velocity = direction.segment<6>(6 * static_cast<Eigen::Index>(b));
    m.blocks[b].speed =
        fastest_corner_speed(m.blocks[b].velocity, block.centroid, block.polygon.vertices);
    m.scale = std::max(m.scale, m.blocks[b].speed);
  }
  if (!(m.scale > 0.0))
    return m;
  for (std::size_t b = 0; b < m.blocks.size(); ++b) {
    MechanismBlock& mb = m.blocks[b];
    mb.velocity /= m.scale;
    mb.speed /= m.scale;
    const Block& block = model.blocks[b];
    mb.motion =
        classify_block_motion(mb.velocity, block.centroid, block.polygon.vertices, mb.speed, 1.0);
  }
  return m;
}

Eigen::VectorXd stacked_velocities(const MechanismBlocks& m) {
  Eigen::VectorXd v(6 * static_cast<Eigen::Index>(m.blocks.size()));
  for (std::size_t b = 0; b < m.blocks.size(); ++b)
    v.segment<6>(6 * static_cast<Eigen::Index>(b)) = m.blocks[b].velocity;
  return v;
}

}  // namespace bimrock
