#pragma once
/// @file A small x-y line plot written as PNG and SVG with cairo (load-displacement curves).
#include <filesystem>
#include <string>
#include <vector>

namespace bimrock {

struct PlotSeries {
  std::string label;
  std::vector<double> x;
  std::vector<double> y;
};

struct LinePlot {
  std::string title;
  std::string x_label;
  std::string y_label;
  std::vector<PlotSeries> series;
  /// Logarithmic axes (decades); values <= 0 are left out.
  bool log_x = false;
  bool log_y = false;
};

/// Writes `<stem>.png` and `<stem>.svg`.
void write_line_plot(const LinePlot& plot, const std::filesystem::path& stem);

/// "Nice" tick values covering [lo, hi] (1, 2 or 5 times a power of ten apart).
std::vector<double> nice_ticks(double lo, double hi, int target_count = 6);

}  // namespace bimrock
