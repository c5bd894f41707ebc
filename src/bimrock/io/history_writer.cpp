#include <bimrock/io/history_writer.hpp>

#include <fstream>
#include <stdexcept>

#include <fmt/core.h>

#include <bimrock/assembly/global_system.hpp>
#include <bimrock/io/line_plot.hpp>

namespace bimrock {

double point_load_resultant(const Stage& stage) {
  Vec2 sum = Vec2::Zero();
  for (const PointLoad& p : stage.loads.points)
    sum += p.force;
  return sum.norm();
}

void write_history_csv(const Model& model, const PlasticResult& result,
                       const std::filesystem::path& file) {
  std::ofstream out(file);
  if (!out)
    throw std::runtime_error("cannot write " + file.string());
  out << "stage,stage_name,increment,stage_factor,point_load_N";
  for (const Monitor& m : model.monitors)
    out << ",ux_" << m.name << "_m,uy_" << m.name << "_m";
  out << ",yielding_points,open_points,lcp_size,active_set_iterations,tangent_factorizations,"
         "pivots,rounds,seconds\n";
  for (const IncrementRecord& r : result.history) {
    const Stage& stage = model.stages[r.stage];
    out << fmt::format("{},{},{},{},{}", r.stage, stage.name, r.increment, r.stage_factor,
                       r.stage_factor * point_load_resultant(stage));
    for (const Vec2& u : r.monitors)
      out << fmt::format(",{},{}", u.x(), u.y());
    out << fmt::format(",{},{},{},{},{},{},{},{}\n", r.yielding_points, r.open_points, r.lcp_size,
                       r.active_set_iterations, r.tangent_factorizations, r.pivots, r.rounds,
                       r.seconds);
  }
}

Vec2 plotted_direction(const Model& model, const Stage& stage) {
  if (stage.control)
    return stage.control->direction.normalized();
  // The resultant force of the stage's loads: the translations' entries of its load vector
  // (Q's first two rows are the identity, eq. 1), summed over the blocks.
  const Eigen::VectorXd p = assemble_loads(model, stage.loads);
  Vec2 total = Vec2::Zero();
  for (int b = 0; b < model.n_blocks(); ++b)
    total += p.segment<2>(6 * b);
  return total.norm() > 0.0 ? Vec2(total.normalized()) : Vec2(Vec2::UnitX());
}

void write_history_plots(const Model& model, const PlasticResult& result,
                         const std::filesystem::path& folder) {
  if (model.stages.empty() || model.monitors.empty())
    return;
  const int last = static_cast<int>(model.stages.size()) - 1;
  const Stage& stage = model.stages[last];
  const double resultant = point_load_resultant(stage);
  const Vec2 along = plotted_direction(model, stage);
  for (std::size_t m = 0; m < model.monitors.size(); ++m) {
    PlotSeries s{model.monitors[m].name, {0.0}, {0.0}};
    for (const IncrementRecord& r : result.history) {
      if (r.stage != last)
        continue;
      s.x.push_back(1e3 * r.monitors[m].dot(along));
      s.y.push_back(resultant > 0.0 ? 1e-3 * r.stage_factor * resultant : r.stage_factor);
    }
    // The first point: the state at the start of the stage (end of the previous one).
    for (auto it = result.history.rbegin(); it != result.history.rend(); ++it) {
      if (it->stage == last - 1) {
        s.x[0] = 1e3 * it->monitors[m].dot(along);
        break;
      }
    }
    LinePlot plot{
        fmt::format("{}: stage '{}'", model.title.empty() ? "bimrock" : model.title, stage.name),
        fmt::format("displacement of {} along ({:.2f}, {:.2f}){} [mm]", model.monitors[m].name,
                    along.x(), along.y(),
                    stage.control ? ", the controlled direction" : ", the load"),
        resultant > 0.0 ? "point load [kN]" : "stage load factor [-]",
        {s}};
    write_line_plot(plot, folder / ("plot_" + model.monitors[m].name));
  }
}

}  // namespace bimrock
