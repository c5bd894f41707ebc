#include <bimrock/io/line_plot.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <cairo-svg.h>
#include <cairo.h>
#include <fmt/core.h>

namespace bimrock {
namespace {

constexpr double kWidth = 640;
constexpr double kHeight = 440;
constexpr double kLeft = 80;
constexpr double kRight = 36;
constexpr double kTop = 40;
constexpr double kBottom = 60;

struct Range {
  double lo = std::numeric_limits<double>::infinity();
  double hi = -std::numeric_limits<double>::infinity();
  void add(double v) {
    if (!std::isfinite(v))
      return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  void settle() {
    if (!(lo <= hi))
      lo = 0.0, hi = 1.0;
    if (hi - lo < 1e-300) {
      const double pad = std::max(std::abs(hi) * 0.1, 1e-12);
      lo -= pad;
      hi += pad;
    }
  }
};

// A value on its axis: its decimal logarithm on a log axis (NaN, left out, for v <= 0).
double on_axis(double v, bool log) {
  if (!log)
    return v;
  return v > 0.0 ? std::log10(v) : std::numeric_limits<double>::quiet_NaN();
}

// Ticks of an axis already transformed: every decade on a log axis, nice values otherwise.
std::vector<double> axis_ticks(const Range& r, bool log) {
  if (!log)
    return nice_ticks(r.lo, r.hi);
  std::vector<double> t;
  for (double k = std::floor(r.lo); k <= std::ceil(r.hi); k += 1.0)
    t.push_back(k);
  return t;
}

std::string tick_label(double t, bool log) {
  return log ? fmt::format("{:g}", std::pow(10.0, t)) : fmt::format("{:.4g}", t);
}

void draw(cairo_t* cr, const LinePlot& plot) {
  Range rx;
  Range ry;
  for (const PlotSeries& s : plot.series) {
    for (double v : s.x)
      rx.add(on_axis(v, plot.log_x));
    for (double v : s.y)
      ry.add(on_axis(v, plot.log_y));
  }
  rx.settle();
  ry.settle();
  const std::vector<double> tx = axis_ticks(rx, plot.log_x);
  const std::vector<double> ty = axis_ticks(ry, plot.log_y);
  rx.lo = std::min(rx.lo, tx.front());
  rx.hi = std::max(rx.hi, tx.back());
  ry.lo = std::min(ry.lo, ty.front());
  ry.hi = std::max(ry.hi, ty.back());
  const double pw = kWidth - kLeft - kRight;
  const double ph = kHeight - kTop - kBottom;
  auto px = [&](double x) {
    return kLeft + (on_axis(x, plot.log_x) - rx.lo) / (rx.hi - rx.lo) * pw;
  };
  auto py = [&](double y) {
    return kTop + ph - (on_axis(y, plot.log_y) - ry.lo) / (ry.hi - ry.lo) * ph;
  };
  auto tick_x = [&](double t) { return kLeft + (t - rx.lo) / (rx.hi - rx.lo) * pw; };
  auto tick_y = [&](double t) { return kTop + ph - (t - ry.lo) / (ry.hi - ry.lo) * ph; };

  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 12);
  cairo_set_line_width(cr, 1.0);
  // Grid and tick labels.
  for (double t : tx) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, tick_x(t), kTop);
    cairo_line_to(cr, tick_x(t), kTop + ph);
    cairo_stroke(cr);
    const std::string label = tick_label(t, plot.log_x);
    cairo_text_extents_t e;
    cairo_text_extents(cr, label.c_str(), &e);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, tick_x(t) - e.width / 2, kTop + ph + 18);
    cairo_show_text(cr, label.c_str());
  }
  for (double t : ty) {
    cairo_set_source_rgb(cr, 0.88, 0.88, 0.88);
    cairo_move_to(cr, kLeft, tick_y(t));
    cairo_line_to(cr, kLeft + pw, tick_y(t));
    cairo_stroke(cr);
    const std::string label = tick_label(t, plot.log_y);
    cairo_text_extents_t e;
    cairo_text_extents(cr, label.c_str(), &e);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, kLeft - e.width - 6, tick_y(t) + e.height / 2);
    cairo_show_text(cr, label.c_str());
  }
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_rectangle(cr, kLeft, kTop, pw, ph);
  cairo_stroke(cr);
  // Titles.
  cairo_text_extents_t e;
  cairo_set_font_size(cr, 14);
  cairo_text_extents(cr, plot.title.c_str(), &e);
  cairo_move_to(cr, kLeft + pw / 2 - e.width / 2, kTop - 14);
  cairo_show_text(cr, plot.title.c_str());
  cairo_set_font_size(cr, 12);
  cairo_text_extents(cr, plot.x_label.c_str(), &e);
  cairo_move_to(cr, kLeft + pw / 2 - e.width / 2, kHeight - 16);
  cairo_show_text(cr, plot.x_label.c_str());
  cairo_save(cr);
  cairo_text_extents(cr, plot.y_label.c_str(), &e);
  cairo_move_to(cr, 20, kTop + ph / 2 + e.width / 2);
  cairo_rotate(cr, -M_PI / 2);
  cairo_show_text(cr, plot.y_label.c_str());
  cairo_restore(cr);
  // Series, with a legend in the upper left corner.
  static constexpr double kColours[][3] = {{0.12, 0.47, 0.71}, {0.84, 0.15, 0.16},
                                           {0.17, 0.63, 0.17}, {1.0, 0.5, 0.05},
                                           {0.58, 0.4, 0.74},  {0.55, 0.34, 0.29}};
  for (std::size_t k = 0; k < plot.series.size(); ++k) {
    const PlotSeries& s = plot.series[k];
    const auto* c = kColours[k % 6];
    cairo_set_source_rgb(cr, c[0], c[1], c[2]);
    cairo_set_line_width(cr, 2.0);
    bool pen_down = false;  // a left-out value (NaN) breaks the line
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      const double x = px(s.x[i]), y = py(s.y[i]);
      if (!std::isfinite(x) || !std::isfinite(y)) {
        pen_down = false;
        continue;
      }
      if (!pen_down)
        cairo_move_to(cr, x, y);
      else
        cairo_line_to(cr, x, y);
      pen_down = true;
    }
    cairo_stroke(cr);
    for (std::size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i) {
      if (!std::isfinite(px(s.x[i])) || !std::isfinite(py(s.y[i])))
        continue;
      cairo_arc(cr, px(s.x[i]), py(s.y[i]), 2.5, 0, 2 * M_PI);
      cairo_fill(cr);
    }
    const double legend_y = kTop + 18 + 16.0 * static_cast<double>(k);
    cairo_move_to(cr, kLeft + 10, legend_y);
    cairo_line_to(cr, kLeft + 30, legend_y);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_move_to(cr, kLeft + 36, legend_y + 4);
    cairo_show_text(cr, s.label.c_str());
  }
}

void check(cairo_surface_t* surface, const std::filesystem::path& file) {
  if (cairo_surface_status(surface) != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write the plot " + file.string());
}

}  // namespace

std::vector<double> nice_ticks(double lo, double hi, int target_count) {
  const double span = hi - lo;
  const double raw = span / std::max(target_count - 1, 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude;
  for (double m : {1.0, 2.0, 5.0, 10.0}) {
    step = m * magnitude;
    if (step >= raw)
      break;
  }
  std::vector<double> ticks;
  for (double t = std::floor(lo / step) * step; t <= hi + 0.5 * step; t += step)
    ticks.push_back(std::abs(t) < 1e-12 * step ? 0.0 : t);
  return ticks;
}

void write_line_plot(const LinePlot& plot, const std::filesystem::path& stem) {
  const std::filesystem::path png = stem.string() + ".png";
  const std::filesystem::path svg = stem.string() + ".svg";
  cairo_surface_t* image =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, int(kWidth), int(kHeight));
  cairo_t* cr = cairo_create(image);
  draw(cr, plot);
  cairo_destroy(cr);
  const cairo_status_t written = cairo_surface_write_to_png(image, png.c_str());
  cairo_surface_destroy(image);
  if (written != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write " + png.string());
  cairo_surface_t* vector = cairo_svg_surface_create(svg.c_str(), kWidth, kHeight);
  check(vector, svg);
  cr = cairo_create(vector);
  draw(cr, plot);
  cairo_destroy(cr);
  cairo_surface_finish(vector);
  check(vector, svg);
  cairo_surface_destroy(vector);
}

}  // namespace bimrock
