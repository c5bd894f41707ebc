#include <bimrock/io/mechanism_table.hpp>

#include <fstream>

#include <fmt/core.h>

#include <bimrock/io/text_file.hpp>

namespace bimrock {

void write_mechanism_csv(const Model& model, const MechanismBlocks& mechanism,
                         const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  out << "block,x0_m,y0_m,u,v,theta_per_m,eps_x_per_m,eps_y_per_m,gamma_xy_per_m,speed,state\n";
  for (std::size_t b = 0; b < mechanism.blocks.size(); ++b) {
    const MechanismBlock& m = mechanism.blocks[b];
    const Vec2& c = model.blocks[b].centroid;
    out << fmt::format("{},{},{}", b, c.x(), c.y());
    for (int k = 0; k < 6; ++k)
      out << ',' << fmt::format("{}", m.velocity(k));
    out << fmt::format(",{},{}\n", m.speed, block_motion_name(m.motion));
  }
  check_written(out, file);
}

}  // namespace bimrock
