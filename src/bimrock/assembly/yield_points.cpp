#include <bimrock/assembly/yield_points.hpp>

#include <map>
#include <tuple>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/model/initial_stress.hpp>

namespace bimrock {

std::vector<YieldPoint> make_yield_points(const Model& model, YieldPointIndex* index) {
  std::vector<YieldPoint> points;
  if (index) {
    index->interface_points.assign(model.interfaces.size(), {-1, -1});
    index->block_points.assign(model.blocks.size(), -1);
    index->spring_points.assign(model.bolt_springs.size(), -1);
  }
  const double t = model.settings.thickness;
  // Merge key: the two blocks and the point, snapped to the model tolerance.
  std::map<std::tuple<int, int, long long, long long>, std::size_t> seen;
  const double snap = std::max(model.tolerance, 1e-300);
  for (int k = 0; k < model.n_interfaces(); ++k) {
    const Interface& f = model.interfaces[k];
    if (f.joint_material < 0 || !model.joint_materials[f.joint_material].strength)
      continue;
    const auto ips = integration_points(f.segment, f.integration);
    for (std::size_t end = 0; end < ips.size(); ++end) {
      const IntegrationPoint& ip = ips[end];
      const auto key = std::make_tuple(f.block_i, f.block_j, std::llround(ip.point.x() / snap),
                                       std::llround(ip.point.y() / snap));
      auto it = seen.find(key);
      if (it != seen.end() && f.integration == Integration::lobatto) {
        points[it->second].weight += t * ip.weight;
        if (index)
          index->interface_points[k][end] = static_cast<int>(it->second);
        continue;
      }
      seen[key] = points.size();
      if (index)
        index->interface_points[k][end] = static_cast<int>(points.size());
      YieldPoint& p =
          points.emplace_back(YieldPoint{YieldPoint::Kind::interface, k, f.block_i, f.block_j,
                                         ip.point, f.normal, t * ip.weight, f.joint_material});
      p.initial.head<2>() = interface_initial_stress(model, f, ip.point);
    }
  }
  for (int b = 0; b < model.n_blocks(); ++b) {
    const Block& block = model.blocks[b];
    if (!model.block_materials[block.material].strength)
      continue;
    if (index)
      index->block_points[b] = static_cast<int>(points.size());
    YieldPoint& p =
        points.emplace_back(YieldPoint{YieldPoint::Kind::block, b, b, kGround, block.centroid,
                                       Vec2::Zero(), t * block.area, block.material});
    p.initial = block_initial_stress(model, b);
  }
  for (int s = 0; s < static_cast<int>(model.bolt_springs.size()); ++s) {
    const BoltSpring& spring = model.bolt_springs[static_cast<std::size_t>(s)];
    if (index)
      index->spring_points[static_cast<std::size_t>(s)] = static_cast<int>(points.size());
    const Bolt& bolt = model.bolts[static_cast<std::size_t>(spring.bolt)];
    YieldPoint& p =
        points.emplace_back(YieldPoint{YieldPoint::Kind::bolt, s, spring.block_a, spring.block_b,
                                       spring.a, spring.axis, bolt.per_model, -1});
    p.initial(0) = bolt.pretension;
  }
  return points;
}

int n_modes(const Model& model, const YieldPoint& p) {
  if (p.is_interface())
    return 3;
  if (p.is_bolt())
    return bolt_of(model, p).shear_capacity ? 3 : 1;
  return model.block_materials[p.material].strength->planes;
}

}  // namespace bimrock
