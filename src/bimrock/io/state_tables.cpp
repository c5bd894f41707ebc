#include <bimrock/io/state_tables.hpp>

#include <fstream>
#include <stdexcept>

#include <fmt/core.h>

#include <bimrock/io/text_file.hpp>

namespace bimrock {

void write_blocks_csv(const Model& model, const ElasticSolution& fields,
                      const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  out << "block,material,x0_m,y0_m,area_m2,u0_m,v0_m,theta_rad,eps_x,eps_y,gamma_xy,"
         "sigma_x_Pa,sigma_y_Pa,tau_xy_Pa,plastic_eps_x,plastic_eps_y,plastic_gamma_xy\n";
  for (int b = 0; b < model.n_blocks(); ++b) {
    const Block& block = model.blocks[static_cast<std::size_t>(b)];
    const BlockState& s = fields.blocks[static_cast<std::size_t>(b)];
    out << fmt::format("{},{},{},{},{}", b,
                       model.block_materials[static_cast<std::size_t>(block.material)].name,
                       block.centroid.x(), block.centroid.y(), block.area);
    for (int k = 0; k < 6; ++k)
      out << ',' << fmt::format("{}", s.d(k));
    for (int k = 0; k < 3; ++k)
      out << ',' << fmt::format("{}", s.stress(k));
    for (int k = 0; k < 3; ++k)
      out << ',' << fmt::format("{}", s.plastic(k));
    out << '\n';
  }
  check_written(out, file);
}

void write_interfaces_csv(const Model& model, const ElasticSolution& fields,
                          const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  out << "interface,block_i,block_j,joint_material,x_a_m,y_a_m,x_b_m,y_b_m,n_x,n_y";
  for (int k = 1; k <= 2; ++k) {
    out << fmt::format(
        ",x{0}_m,y{0}_m,delta_n{0}_m,delta_s{0}_m,sigma_n{0}_Pa,tau{0}_Pa,"
        "plastic_n{0}_m,plastic_s{0}_m",
        k);
  }
  out << '\n';
  for (int f = 0; f < model.n_interfaces(); ++f) {
    const Interface& face = model.interfaces[static_cast<std::size_t>(f)];
    const std::string material =
        face.joint_material >= 0
            ? model.joint_materials[static_cast<std::size_t>(face.joint_material)].name
            : std::string("rigid");
    out << fmt::format("{},{},{},{},{},{},{},{},{},{}", f, face.block_i, face.block_j, material,
                       face.segment.a.x(), face.segment.a.y(), face.segment.b.x(),
                       face.segment.b.y(), face.normal.x(), face.normal.y());
    for (const InterfacePointState& p : fields.interfaces[static_cast<std::size_t>(f)]) {
      out << fmt::format(",{},{},{},{},{},{},{},{}", p.point.x(), p.point.y(), p.delta(0),
                         p.delta(1), p.stress(0), p.stress(1), p.plastic(0), p.plastic(1));
    }
    out << '\n';
  }
  check_written(out, file);
}

namespace {

// A CSV field holding free text: quoted, its quotes doubled (RFC 4180).
std::string csv_text(const std::string& s) {
  std::string out = "\"";
  for (const char c : s) {
    if (c == '"')
      out += '"';
    out += c;
  }
  return out + '"';
}

}  // namespace

void write_bolts_csv(const Model& model, const ElasticSolution& fields,
                     const std::filesystem::path& file) {
  std::ofstream out = open_for_writing(file);
  out << "spring,bolt,name,kind,installed_stage,block_a,block_b,x_a_m,y_a_m,x_b_m,y_b_m,standing,"
         "axial_force_N,shear_force_N,elongation_m,shear_displacement_m,plastic_elongation_m,"
         "plastic_shear_m,axial_capacity_used,yielded\n";
  for (std::size_t k = 0; k < model.bolt_springs.size(); ++k) {
    const BoltSpring& s = model.bolt_springs[k];
    const Bolt& bolt = model.bolts[static_cast<std::size_t>(s.bolt)];
    const SpringState& r = fields.springs[k];
    out << fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{},{}\n", k, s.bolt,
                       csv_text(bolt.name),
                       bolt.kind == BoltSpec::Kind::anchored ? "anchored" : "grouted", bolt.stage,
                       s.block_a, s.block_b, s.a.x(), s.a.y(), s.b.x(), s.b.y(), r.standing ? 1 : 0,
                       r.force(0), r.force(1), r.delta(0), r.delta(1), r.plastic(0), r.plastic(1),
                       r.capacity_used, r.yielded ? 1 : 0);
  }
  check_written(out, file);
}

}  // namespace bimrock
