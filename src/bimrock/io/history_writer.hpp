#pragma once
/// @file The increment history of a nonlinear analysis: history.csv and one load-displacement
/// plot per monitor (PNG and SVG).
#include <filesystem>

#include <bimrock/analysis/plastic_analysis.hpp>

namespace bimrock {

/// history.csv: one row per carried increment: stage, increment, stage factor, the load of the
/// stage's point loads (factor times their resultant, N), each monitor's ux and uy [m], yielding
/// and open points, LCP size, pivots, candidate rounds, seconds.
void write_history_csv(const Model& model, const PlasticResult& result,
                       const std::filesystem::path& file);

/// plot_<monitor>.png/.svg: the load of the last stage against the monitor's displacement
/// along plotted_direction() (mm), one curve per monitor.
void write_history_plots(const Model& model, const PlasticResult& result,
                         const std::filesystem::path& folder);

/// Magnitude of the resultant of a stage's point loads [N] (0 when it has none).
double point_load_resultant(const Stage& stage);

/// The direction a stage's load-displacement curves are drawn along (and say so on their axis):
/// the controlled direction, else the resultant of the stage's loads (point loads, tractions,
/// weight), else x. Unit length.
Vec2 plotted_direction(const Model& model, const Stage& stage);

}  // namespace bimrock
