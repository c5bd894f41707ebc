#include "bimrock/app/report.hpp"

#include <algorithm>
#include <string>

#include <fmt/core.h>

#include <bimrock/analysis/memory_estimate.hpp>
#include <bimrock/io/factor_of_safety_text.hpp>

namespace bimrock {

void print_model(const Model& model) {
  int supports = 0;
  for (const Interface& f : model.interfaces)
    supports += f.is_support() ? 1 : 0;
  fmt::print("{}: {} blocks, {} interfaces between blocks, {} support interfaces, {} unknowns\n",
             model.source_file, model.n_blocks(), model.n_interfaces() - supports, supports,
             model.n_dofs());
  fmt::print("length tolerance {:.3g} m; the case is valid\n", model.tolerance);
}

void print_memory_estimate(const Model& model) {
  const MemoryEstimate e = estimate_memory(model);
  constexpr double kMiB = 1048576.0;
  const std::string peak =
      model.stages.empty()
          ? fmt::format("about {:.0f} MiB", e.peak_bytes / kMiB)
          : fmt::format("from {:.0f} to about {:.0f} MiB, the more the larger its plastic zone",
                        e.peak_bytes / kMiB, e.nonlinear_bytes / kMiB);
  fmt::print(
      "memory: the run's peak {} ({:.0f} MiB now with the model; K and its Cholesky factor of "
      "about {} non-zeros {:.1f} MiB)\n",
      peak, e.now_bytes / kMiB, e.factor_nonzeros, e.solve_bytes / kMiB);
}

namespace {

void print_monitors(const Model& model, const ElasticSolution& s) {
  for (std::size_t k = 0; k < model.monitors.size(); ++k) {
    fmt::print("monitor {:>10}: ux = {:.6e} m, uy = {:.6e} m\n", model.monitors[k].name,
               s.monitor_displacements[k].x(), s.monitor_displacements[k].y());
  }
}

void print_timings(const Timings& t) {
  std::string phases;
  for (const auto& [name, seconds] : t.phases)
    phases += fmt::format(" {} {:.3f} s,", name, seconds);
  fmt::print("time:{} total {:.3f} s\n", phases, t.total());
}

}  // namespace

void print_summary(const Model& model, const ElasticSolution& s, const std::filesystem::path& out) {
  print_model(model);
  fmt::print("mean strain of the mass: eps_x = {:.6e}, eps_y = {:.6e}, gamma_xy = {:.6e}\n",
             s.mean_strain(0), s.mean_strain(1), s.mean_strain(2));
  print_monitors(model, s);
  print_timings(s.timings);
  fmt::print("results written to {}/\n", out.string());
}

void print_increment(const Model& model, const IncrementRecord& r, double elapsed) {
  const Stage& stage = model.stages[static_cast<std::size_t>(r.stage)];
  // Progress in increments asked for: the stages before whole, this one by its factor (under
  // displacement control the factor is the load's, so the step count stands in for it).
  double total = 0.0;
  double done = 0.0;
  for (std::size_t k = 0; k < model.stages.size(); ++k) {
    const double n = model.stages[k].increments;
    total += n;
    if (static_cast<int>(k) < r.stage)
      done += n;
  }
  done += stage.control ? std::min<double>(r.increment, stage.increments)
                        : std::clamp(r.stage_factor, 0.0, 1.0) * stage.increments;
  // Below a hundredth of an increment done, the rate says nothing of the time left (a part of
  // round-off size carried would promise years).
  const std::string left = done >= 0.01
                               ? fmt::format("about {:.0f} s left", elapsed * (total - done) / done)
                               : std::string("time left unknown");
  fmt::print(
      "stage {}/{} {:>12} step {:>3} of {}: factor {:.6f}, yielding points {:>5}, open {:>5}, "
      "LCP {:>5} rows; {:.1f} s, {}\n",
      r.stage + 1, model.stages.size(), stage.name, r.increment, stage.increments, r.stage_factor,
      r.yielding_points, r.open_points, r.lcp_size, elapsed, left);
}

void print_plastic_summary(const Model& model, const PlasticResult& result,
                           const ElasticSolution& fields, const std::filesystem::path& out) {
  print_model(model);
  if (result.initial_stress) {
    const InitialStressCheck& i = *result.initial_stress;
    fmt::print(
        "initial stress: the first stage's loads less its internal forces: largest {:.3g} N "
        "({:.2g} of the largest force){}\n",
        i.residual, i.relative_residual,
        i.violated_points > 0
            ? fmt::format("; {} points outside their strength yield in the first stage",
                          i.violated_points)
            : std::string());
  }
  print_monitors(model, fields);
  if (result.collapse) {
    const Collapse& c = *result.collapse;
    const Stage& stage = model.stages[static_cast<std::size_t>(c.stage)];
    Vec2 load = Vec2::Zero();
    for (const PointLoad& p : stage.loads.points)
      load += p.force;
    if (c.unstable_at_first_load)
      fmt::print(
          "UNSTABLE under the first load of stage '{}': no equilibrium from factor {:.3g} of it "
          "on",
          stage.name, c.failed);
    else if (c.limit_point)
      fmt::print(
          "COLLAPSE in stage '{}': limit load at factor {:.6f}, the peak of the equilibrium path "
          "(past the last load carried under load control, displacement control of block {}: "
          "the load {} {:.3g} m; the stage's whole load moves it {:.3g} m elastically)",
          stage.name, c.carried, c.control_block,
          c.fell ? "fell past the peak after it moved at the peak for"
                 : "stayed there while it moved",
          c.plateau, c.elastic);
    else
      fmt::print("COLLAPSE in stage '{}': carried factor {:.6f}, failed at {:.6f}", stage.name,
                 c.carried, c.failed);
    if (load.norm() > 0.0 && c.limit_point)
      fmt::print(" (point load {:.6g} N)", c.carried * load.norm());
    else if (load.norm() > 0.0 && !c.unstable_at_first_load)
      fmt::print(" (point load between {:.6g} N and {:.6g} N)", c.carried * load.norm(),
                 c.failed * load.norm());
    fmt::print("; {} yield modes in the mechanism (summary.json, collapse.png)\n",
               c.mechanism.size());
    if (c.associated_bound)
      fmt::print(
          "  load control stopped undecided at the carried factor; the failed factor is where the "
          "same case with associated flow (each dilation equal to its friction) is proven to "
          "fail, and no flow rule carries more (static theorem)\n");
    else if (c.undecided_inside)
      fmt::print(
          "  the bracket is wider than its tolerance: the loads inside it could be neither carried "
          "nor proven to fail (with non-associated flow, the upper end can be the associated "
          "limit load); a displacement-controlled stage (stages[].control) follows the path "
          "past its peak\n");
  } else if (result.stopped) {
    const Stop& st = *result.stopped;
    fmt::print("STOPPED in stage '{}' at factor {:.6f}: {}; the carried increments are written\n",
               model.stages[static_cast<std::size_t>(st.stage)].name, st.factor, st.reason);
  } else {
    fmt::print("all {} stages carried\n", model.stages.size());
  }
  if (result.factor_of_safety)
    fmt::print("{}\n", factor_of_safety_text(*result.factor_of_safety));
  print_timings(result.timings);
  fmt::print("results written to {}/\n", out.string());
}

}  // namespace bimrock
