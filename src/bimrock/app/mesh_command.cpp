#include "bimrock/app/mesh_command.hpp"

#include <map>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include <bimrock/analysis/elastic_analysis.hpp>
#include <bimrock/io/block_picture.hpp>
#include <bimrock/io/case_reader.hpp>
#include <bimrock/io/output_folder.hpp>
#include <bimrock/io/results_writer.hpp>
#include <bimrock/io/run_summary.hpp>
#include <bimrock/io/vtk_writer.hpp>
#include <bimrock/model/limits.hpp>

namespace bimrock {

void run_mesh(const std::string& case_file, const std::filesystem::path& out, bool quiet) {
  const Case c = read_case_file(case_file);
  const Model model = build_model(c.spec);
  // The output within limits.output_mb, checked before anything is written, as `run` does.
  const double mb = (estimate_vtu_step_bytes(model) + 1e6) / 1e6;  // 1 MB: picture, summary
  if (mb > c.spec.limits.output_mb) {
    const auto line = c.spec.limits.lines.find("limits.output_mb");
    throw InputError(c.spec.file, line == c.spec.limits.lines.end() ? 0 : line->second, "output",
                     limit_message(mb, c.spec.limits.output_mb, "output_mb",
                                   "MB of blocks.vtu and pictures", "give fewer blocks"));
  }
  StagingFolder folder(out);
  ElasticSolution undisplaced;
  undisplaced.u = Eigen::VectorXd::Zero(model.n_dofs());
  evaluate_fields(model, undisplaced);
  write_vtu(model, undisplaced, {}, folder.path() / "blocks.vtu");
  // No picture of more blocks than a run draws (a grey blur, slow to draw): ParaView then.
  const bool picture = model.n_blocks() <= kMaxPictureBlocks;
  if (picture) {
    const std::vector<Vec2>& water =
        model.stages.empty() ? model.loads.water_surface : model.stages.back().loads.water_surface;
    write_block_picture(model,
                        {model.title.empty() ? "blocks" : model.title, {}, 0.05, {}, 1400, water},
                        folder.path() / "blocks");
  }

  std::map<std::string, int> blocks_by_material, interfaces_by_material;
  for (const Block& b : model.blocks)
    ++blocks_by_material[model.block_materials[static_cast<std::size_t>(b.material)].name];
  int supports = 0;
  for (const Interface& f : model.interfaces) {
    if (f.is_support()) {
      ++supports;
      continue;
    }
    ++interfaces_by_material[model.joint_materials[static_cast<std::size_t>(f.joint_material)]
                                 .name];
  }
  double min_area = model.blocks.empty() ? 0.0 : model.blocks.front().area, max_area = min_area;
  for (const Block& b : model.blocks) {
    min_area = std::min(min_area, b.area);
    max_area = std::max(max_area, b.area);
  }
  std::vector<std::string> files = {"blocks.vtu"};
  if (picture)
    files.insert(files.end(), {"blocks.png", "blocks.svg"});
  const nlohmann::json summary = {{"program", "bimrock mesh"},
                                  {"case", case_file},
                                  {"units", "SI: m"},
                                  {"blocks", model.n_blocks()},
                                  {"interfaces", model.n_interfaces() - supports},
                                  {"support_interfaces", supports},
                                  {"area_m2", total_area(model)},
                                  {"smallest_block_m2", min_area},
                                  {"largest_block_m2", max_area},
                                  {"blocks_by_material", blocks_by_material},
                                  {"interfaces_by_joint_material", interfaces_by_material},
                                  {"files", files}};
  write_json(summary, folder.path() / "summary.json");
  folder.commit();
  if (quiet)
    return;
  fmt::print(
      "{}: {} blocks (area {:.6g} m^2, from {:.3g} to {:.3g} m^2 each), {} interfaces, {} support "
      "interfaces\n",
      case_file, model.n_blocks(), total_area(model), min_area, max_area,
      model.n_interfaces() - supports, supports);
  for (const auto& [name, n] : interfaces_by_material)
    fmt::print("  {:>6} interfaces of {}\n", n, name);
  fmt::print("blocks written to {}/ (blocks.vtu for ParaView{})\n", out.string(),
             picture ? std::string(", blocks.png")
                     : fmt::format("; no picture of more than {} blocks", kMaxPictureBlocks));
}

}  // namespace bimrock
