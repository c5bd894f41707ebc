#include <bimrock/io/results_writer.hpp>

#include <fmt/core.h>
#include <cmath>

#include <bimrock/model/limits.hpp>

#include <bimrock/io/block_picture.hpp>
#include <bimrock/io/history_writer.hpp>
#include <bimrock/io/line_plot.hpp>
#include <bimrock/io/mechanism_table.hpp>
#include <bimrock/io/run_summary.hpp>
#include <bimrock/io/state_tables.hpp>
#include <bimrock/model/bolts.hpp>
#include <bimrock/model/stage_blocks.hpp>

namespace bimrock {

namespace fs = std::filesystem;

namespace {

/// The phreatic surface in force during stage `stage` (-1: the elastic analysis's loads).
std::vector<Vec2> water_surface(const Model& model, int stage) {
  return stage < 0 ? model.loads.water_surface
                   : model.stages[static_cast<std::size_t>(stage)].loads.water_surface;
}

std::string step_file(std::size_t step) {
  return fmt::format("vtk/step_{:04d}.vtu", step);
}

/// The files every run writes for its final state; appends their names to `files`.
void write_final_state(const Model& model, const ElasticSolution& fields,
                       const OutputOptions& options, const fs::path& folder,
                       std::vector<std::string>& files) {
  if (options.csv) {
    write_blocks_csv(model, fields, folder / "blocks.csv");
    write_interfaces_csv(model, fields, folder / "interfaces.csv");
    files.insert(files.end(), {"blocks.csv", "interfaces.csv"});
    if (!model.bolts.empty()) {
      write_bolts_csv(model, fields, folder / "bolts.csv");
      files.push_back("bolts.csv");
    }
  }
}

// The interface marks of a collapse mechanism: its slipping and opening joints.
std::vector<InterfaceMark> mechanism_marks(const Model& model,
                                           const std::vector<YieldPoint>& points,
                                           const Collapse& collapse) {
  std::vector<InterfaceMark> marks(static_cast<std::size_t>(model.n_interfaces()),
                                   InterfaceMark::none);
  for (std::size_t f = 0; f < marks.size(); ++f) {
    if (model.interfaces[f].joint_material >= 0 && !model.interfaces[f].is_support())
      marks[f] = InterfaceMark::joint;
  }
  for (const MechanismEntry& e : collapse.mechanism) {
    const YieldPoint& p = points[static_cast<std::size_t>(e.point)];
    if (!p.is_interface())
      continue;
    marks[static_cast<std::size_t>(p.owner)] =
        e.mode == 2 ? InterfaceMark::opening : InterfaceMark::slipping;
  }
  return marks;
}

// The interface marks of a state: the joints that have slipped and those open (continuum
// interfaces only where they have).
std::vector<InterfaceMark> state_marks(const Model& model, const YieldPointIndex& index,
                                       const std::vector<PlasticState>& states) {
  std::vector<InterfaceMark> marks(static_cast<std::size_t>(model.n_interfaces()),
                                   InterfaceMark::none);
  for (std::size_t f = 0; f < marks.size(); ++f) {
    if (model.interfaces[f].joint_material < 0 || model.interfaces[f].is_support())
      continue;
    const bool continuum =
        model.joint_materials[static_cast<std::size_t>(model.interfaces[f].joint_material)].kind ==
        JointMaterial::Kind::continuum;
    marks[f] = continuum ? InterfaceMark::none : InterfaceMark::joint;
    for (const int p : index.interface_points[f]) {
      if (p < 0)
        continue;
      const PlasticState& s = states[static_cast<std::size_t>(p)];
      if (s.gap > 0.0)
        marks[f] = InterfaceMark::opening;
      else if (s.slip > 0.0 && marks[f] != InterfaceMark::opening)
        marks[f] = InterfaceMark::slipping;
    }
  }
  return marks;
}

// The factor of safety's pictures: F against the largest plastic multiplier of its step, and the
// mechanism at the smallest F that fails.
void write_factor_of_safety(const Model& model, const PlasticResult& result, const fs::path& dir,
                            std::vector<std::string>& files) {
  const FactorOfSafety& f = *result.factor_of_safety;
  // The monitors' displacements since F = 1 where there are monitors, else each step's largest
  // plastic multiplier.
  std::vector<PlotSeries> series;
  for (std::size_t m = 0; m < model.monitors.size(); ++m) {
    PlotSeries s{"monitor " + model.monitors[m].name, {}, {}};
    for (const FactorTrial& t : f.trials) {
      s.x.push_back(t.factor);
      s.y.push_back(t.monitors[m].norm());
    }
    series.push_back(std::move(s));
  }
  if (series.empty()) {
    PlotSeries s{"largest plastic multiplier of the step", {}, {}};
    for (const FactorTrial& t : f.trials) {
      s.x.push_back(t.factor);
      s.y.push_back(t.largest_flow);
    }
    series.push_back(std::move(s));
  }
  write_line_plot({"factor of safety: strength reduction", "F (strengths divided by F)",
                   model.monitors.empty() ? "largest plastic multiplier of the step [m]"
                                          : "displacement since F = 1 [m]",
                   series},
                  dir / "fos_trials");
  files.insert(files.end(), {"fos_trials.png", "fos_trials.svg"});
  if (f.collapse && f.collapse->direction.size() == model.n_dofs() &&
      model.n_blocks() <= kMaxPictureBlocks) {
    write_block_picture(
        model,
        {fmt::format("mechanism at F = {:.4g} (red: slipping joints, blue: opening)",
                     f.collapse->failed),
         f.collapse->direction, 0.08, mechanism_marks(model, result.points, *f.collapse), 1000,
         water_surface(model, f.stage)},
        dir / "fos_mechanism");
    files.insert(files.end(), {"fos_mechanism.png", "fos_mechanism.svg"});
  }
  if (f.collapse && f.collapse->direction.size() == model.n_dofs()) {
    write_mechanism_csv(model, mechanism_blocks(model, f.collapse->direction),
                        dir / "fos_mechanism.csv");
    files.push_back("fos_mechanism.csv");
  }
}

}  // namespace

namespace {

/// The points of a VTK step: the blocks' vertices and two per interface.
double vtu_points(const Model& model) {
  double vertices = 0.0;
  for (const Block& b : model.blocks)
    vertices += static_cast<double>(b.polygon.vertices.size());
  return vertices + 2.0 * (model.n_interfaces() + static_cast<double>(model.bolt_springs.size()));
}

// Blocks, interfaces and bolt springs (all springs: at most, they stand).
double vtu_cells(const Model& model) {
  return model.n_blocks() + model.n_interfaces() + static_cast<double>(model.bolt_springs.size());
}

}  // namespace

double estimate_vtu_step_bytes(const Model& model) {
  // A .vtu step (vtk_writer.cpp), Base64 (4/3): per point its coordinates, displacement and
  // connectivity (7 x 8 bytes); per cell its offset, type and 23 numbers of cell data.
  return 4.0 / 3.0 * (56.0 * vtu_points(model) + 193.0 * vtu_cells(model)) + 4096.0;
}

double estimate_output_bytes(const Model& model, const OutputOptions& options) {
  const double points = vtu_points(model);
  const double cells = vtu_cells(model);
  const double step = estimate_vtu_step_bytes(model);
  double increments = 0.0;
  for (const Stage& s : model.stages)
    increments += s.increments;
  const double steps = model.stages.empty() ? 1.0 : std::ceil(increments / options.vtk_every) + 2.0;
  // The tables of the final state and the history: a few hundred bytes per row.
  const double tables = options.csv ? 200.0 * cells : 0.0;
  const double history = 200.0 * (1.0 + static_cast<double>(model.monitors.size())) * steps;
  // On collapse: mechanism.csv (about 150 bytes a block), the block lists in summary.json, and
  // the last step's point array of mechanism velocities (3 values a point, Base64).
  const double mechanism =
      160.0 * model.n_blocks() + (options.vtk ? 4.0 / 3.0 * 24.0 * points : 0.0);
  const double pictures_and_summary = 1e6;
  return (options.vtk ? steps * step : 0.0) + tables + history + mechanism + pictures_and_summary;
}

void check_output_size(const Model& model, const Case& c) {
  const double mb = estimate_output_bytes(model, c.output) / 1e6;
  const CaseLimits& limits = c.spec.limits;
  if (mb <= limits.output_mb)
    return;
  const auto line = limits.lines.find("limits.output_mb");
  throw InputError(c.spec.file, line == limits.lines.end() ? 0 : line->second, "output",
                   limit_message(mb, limits.output_mb, "output_mb", "MB of results",
                                 c.output.vtk ? "give fewer increments, set output.vtk_every to "
                                                "write fewer steps, or set output.vtk: false"
                                              : "give fewer increments"));
}

void write_elastic_results(const Model& model, const ElasticSolution& solution,
                           const OutputOptions& options, const fs::path& out) {
  StagingFolder folder(out);
  std::vector<std::string> files;
  write_final_state(model, solution, options, folder.path(), files);
  if (options.vtk) {
    fs::create_directory(folder.path() / "vtk");
    write_vtu(model, solution, {}, folder.path() / step_file(1));
    write_pvd({{1.0, step_file(1)}}, folder.path() / "results.pvd");
    files.insert(files.end(), {step_file(1), "results.pvd"});
  }
  if (model.n_blocks() <= kMaxPictureBlocks) {
    write_block_picture(
        model, {"displaced (magnified)", solution.u, 0.05, {}, 1000, water_surface(model, -1)},
        folder.path() / "displaced");
    files.insert(files.end(), {"displaced.png", "displaced.svg"});
  }
  write_json(run_summary(model, solution, nullptr, files), folder.path() / "summary.json");
  folder.commit();
}

PlasticResultsWriter::PlasticResultsWriter(const Model& model, OutputOptions options,
                                           const fs::path& out)
    : model_(model), options_(options), folder_(out) {
  const std::size_t n_points = make_yield_points(model_, &index_).size();
  if (options_.vtk) {
    fs::create_directory(folder_.path() / "vtk");
    AnalysisState start;
    start.u = Eigen::VectorXd::Zero(model_.n_dofs());
    start.points.assign(n_points, PlasticState{});
    write_vtu(model_, fields_of(start, -1), {&index_, &start.points},
              folder_.path() / step_file(0));
    steps_.push_back({0.0, step_file(0)});
  }
}

ElasticSolution PlasticResultsWriter::fields_of(const AnalysisState& state, int stage) const {
  ElasticSolution fields;
  fields.u = state.u;
  evaluate_fields(model_, fields, {&index_, &state.points, &state.installed});
  fields.springs =
      spring_states(model_, springs_present(model_, stage), state.u, {&index_, &state.points});
  return fields;
}

void PlasticResultsWriter::on_increment(const IncrementRecord& record, const AnalysisState& state) {
  ++carried_;
  if (!options_.vtk)
    return;
  if (carried_ % options_.vtk_every != 0) {
    unwritten_ = state;  // written in finish() if it is the last
    unwritten_stage_ = record.stage;
    return;
  }
  unwritten_.reset();
  const std::size_t step = steps_.size();
  write_vtu(model_, fields_of(state, record.stage), {&index_, &state.points},
            folder_.path() / step_file(step));
  steps_.push_back({static_cast<double>(carried_), step_file(step)});
}

ElasticSolution PlasticResultsWriter::finish(const PlasticResult& result) {
  const fs::path& dir = folder_.path();
  if (unwritten_) {  // the last carried increment, which thinning skipped
    const std::size_t step = steps_.size();
    write_vtu(model_, fields_of(*unwritten_, unwritten_stage_), {&index_, &unwritten_->points},
              dir / step_file(step));
    steps_.push_back({static_cast<double>(carried_), step_file(step)});
    unwritten_.reset();
  }
  // The stage the run ended in: where it collapsed or stopped, else the last.
  const int stage = result.collapse  ? result.collapse->stage
                    : result.stopped ? result.stopped->stage
                                     : static_cast<int>(model_.stages.size()) - 1;
  ElasticSolution fields = fields_of(result.state, stage);
  fields.timings = result.timings;
  std::vector<std::string> files;
  write_final_state(model_, fields, options_, dir, files);
  write_history_csv(model_, result, dir / "history.csv");
  files.push_back("history.csv");
  write_history_plots(model_, result, dir);
  if (result.collapse && result.collapse->direction.size() == model_.n_dofs()) {
    const MechanismBlocks mechanism = mechanism_blocks(model_, result.collapse->direction);
    write_mechanism_csv(model_, mechanism, dir / "mechanism.csv");
    files.push_back("mechanism.csv");
    if (options_.vtk && !steps_.empty()) {
      // The last step written again, now that the collapse is known, with the mechanism's
      // velocities as a point array.
      const Eigen::VectorXd velocities = stacked_velocities(mechanism);
      write_vtu(model_, fields, {&index_, &result.state.points}, dir / steps_.back().file,
                &velocities);
    }
  }
  for (const Monitor& m : model_.monitors)
    files.insert(files.end(), {"plot_" + m.name + ".png", "plot_" + m.name + ".svg"});
  if (options_.vtk) {
    write_pvd(steps_, dir / "results.pvd");
    for (const PvdEntry& s : steps_)
      files.push_back(s.file);
    files.push_back("results.pvd");
  }
  if (model_.n_blocks() <= kMaxPictureBlocks) {
    // The blocks standing at the end (an excavated block keeps the displacement it had).
    const std::vector<char> present = blocks_present(model_, stage);
    std::vector<double> bolt_use(fields.springs.size(), NAN);
    for (std::size_t k = 0; k < bolt_use.size(); ++k)
      if (fields.springs[k].standing)
        bolt_use[k] = fields.springs[k].capacity_used;
    write_block_picture(model_,
                        {"final state (displacements magnified)", fields.u, 0.05,
                         state_marks(model_, index_, result.state.points), 1000,
                         water_surface(model_, stage), present, bolt_use},
                        dir / "final");
    files.insert(files.end(), {"final.png", "final.svg"});
    if (result.collapse && result.collapse->direction.size() == model_.n_dofs()) {
      write_block_picture(
          model_,
          {"collapse mechanism (red: slipping joints, blue: opening)", result.collapse->direction,
           0.08, mechanism_marks(model_, result.points, *result.collapse), 1000,
           water_surface(model_, stage), present},
          dir / "collapse");
      files.insert(files.end(), {"collapse.png", "collapse.svg"});
    }
  }
  if (result.factor_of_safety)
    write_factor_of_safety(model_, result, dir, files);
  write_json(run_summary(model_, fields, &result, files), dir / "summary.json");
  folder_.commit();
  return fields;
}

}  // namespace bimrock
