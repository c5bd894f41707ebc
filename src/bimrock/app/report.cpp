#include "bimrock/app/report.hpp"

#include <fmt/core.h>

namespace bimrock {

void print_model(const Model& model) {
  int supports = 0;
  for (const Interface& f : model.interfaces) supports += f.is_support() ? 1 : 0;
  fmt::print("{}: {} blocks, {} interfaces between blocks, {} support interfaces, {} unknowns\n",
             model.source_file, model.n_blocks(), model.n_interfaces() - supports, supports,
             model.n_dofs());
  fmt::print("length tolerance {:.3g} m; the case is valid\n", model.tolerance);
}

void print_summary(const Model& model, const ElasticSolution& s, const std::filesystem::path& out) {
  print_model(model);
  fmt::print("mean strain of the mass: eps_x = {:.6e}, eps_y = {:.6e}, gamma_xy = {:.6e}\n",
             s.mean_strain(0), s.mean_strain(1), s.mean_strain(2));
  for (std::size_t k = 0; k < model.monitors.size(); ++k) {
    fmt::print("monitor {:>10}: ux = {:.6e} m, uy = {:.6e} m\n", model.monitors[k].name,
               s.monitor_displacements[k].x(), s.monitor_displacements[k].y());
  }
  std::string phases;
  for (const auto& [name, seconds] : s.timings.phases) phases += fmt::format(" {} {:.3f} s,", name, seconds);
  fmt::print("time:{} total {:.3f} s\n", phases, s.timings.total());
  fmt::print("results written to {}/\n", out.string());
}

}  // namespace bimrock
