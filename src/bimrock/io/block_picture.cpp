#include <bimrock/io/block_picture.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <cairo-svg.h>
#include <cairo.h>

#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/model/water_pressure.hpp>

namespace bimrock {
namespace {

constexpr double kMargin = 30.0;
constexpr double kTitle = 30.0;
constexpr double kFooter = 28.0;  // the scale bar, the magnification and the materials' legend

/// Fill colours of the block materials, in the order of the case file (then again).
constexpr double kMaterialColours[][3] = {
    {0.90, 0.85, 0.76}, {0.72, 0.82, 0.90}, {0.80, 0.90, 0.74}, {0.95, 0.78, 0.70},
    {0.85, 0.78, 0.92}, {0.93, 0.90, 0.65}, {0.75, 0.88, 0.86}, {0.88, 0.80, 0.80}};
constexpr std::size_t kColours = sizeof(kMaterialColours) / sizeof(kMaterialColours[0]);

struct Frame {
  BBox box;
  double scale = 1.0;
  double height = 0.0;
  [[nodiscard]] double x(double wx) const { return kMargin + (wx - box.lo.x()) * scale; }
  [[nodiscard]] double y(double wy) const {
    return height - kMargin - kFooter - (wy - box.lo.y()) * scale;
  }
};

Vec2 moved(const Model& m, int block, const Vec2& p, const Eigen::VectorXd& u, double magnify) {
  if (u.size() == 0)
    return p;
  return p + magnify * (block_Q(m.blocks[block].centroid, p) * u.segment<6>(6 * block));
}

void polygon_path(cairo_t* cr, const Frame& f, const Model& m, int block, const Eigen::VectorXd& u,
                  double magnify) {
  const auto& v = m.blocks[block].polygon.vertices;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const Vec2 p = moved(m, block, v[k], u, magnify);
    if (k == 0)
      cairo_move_to(cr, f.x(p.x()), f.y(p.y()));
    else
      cairo_line_to(cr, f.x(p.x()), f.y(p.y()));
  }
  cairo_close_path(cr);
}

/// The phreatic surface, dashed blue, across the drawing's width, its height kept within a
/// diagonal of the drawing (cairo's coordinates are bounded).
void draw_water_surface(cairo_t* cr, const std::vector<Vec2>& surface, const Frame& f) {
  if (surface.empty())
    return;
  std::vector<double> xs = {f.box.lo.x()};
  for (const Vec2& p : surface) {
    if (p.x() > f.box.lo.x() && p.x() < f.box.hi.x())
      xs.push_back(p.x());
  }
  xs.push_back(f.box.hi.x());
  const double reach = f.box.diagonal();
  cairo_set_source_rgb(cr, 0.1, 0.45, 0.85);
  cairo_set_line_width(cr, 1.5);
  const double dash[] = {6.0, 3.0};
  cairo_set_dash(cr, dash, 2, 0.0);
  for (std::size_t k = 0; k < xs.size(); ++k) {
    const double y =
        std::clamp(phreatic_height(surface, xs[k]), f.box.lo.y() - reach, f.box.hi.y() + reach);
    if (k == 0)
      cairo_move_to(cr, f.x(xs[k]), f.y(y));
    else
      cairo_line_to(cr, f.x(xs[k]), f.y(y));
  }
  cairo_stroke(cr);
  cairo_set_dash(cr, nullptr, 0, 0.0);
}

void draw(cairo_t* cr, const Model& m, const BlockPicture& pic, const Frame& f, double width) {
  cairo_set_source_rgb(cr, 1, 1, 1);
  cairo_paint(cr);
  const double magnify =
      displacement_magnification(m, pic.u, pic.displayed_fraction, f.box.diagonal(), pic.present);
  const auto drawn = [&](int b) {
    return pic.present.empty() || pic.present[static_cast<std::size_t>(b)] != 0;
  };
  const Eigen::VectorXd none;
  cairo_set_line_join(cr, CAIRO_LINE_JOIN_ROUND);
  if (magnify > 0.0) {
    cairo_set_source_rgb(cr, 0.75, 0.75, 0.75);
    cairo_set_line_width(cr, 0.8);
    for (int b = 0; b < m.n_blocks(); ++b) {
      polygon_path(cr, f, m, b, none, 0.0);
      cairo_stroke(cr);
    }
  }
  for (int b = 0; b < m.n_blocks(); ++b) {
    if (!drawn(b))
      continue;
    polygon_path(cr, f, m, b, pic.u, magnify);
    const double* fill =
        kMaterialColours[static_cast<std::size_t>(m.blocks[b].material) % kColours];
    cairo_set_source_rgb(cr, fill[0], fill[1], fill[2]);
    cairo_fill_preserve(cr);
    cairo_set_source_rgb(cr, 0.35, 0.3, 0.25);
    cairo_set_line_width(cr, 0.6);
    cairo_stroke(cr);
  }
  // Supports: a dark line along the held edges.
  for (int k = 0; k < m.n_interfaces(); ++k) {
    const Interface& in = m.interfaces[k];
    InterfaceMark mark = pic.marks.empty() ? InterfaceMark::joint : pic.marks[k];
    if (!drawn(in.block_i) || (!in.is_support() && !drawn(in.block_j)))
      continue;
    if (in.is_support()) {
      cairo_set_source_rgb(cr, 0.1, 0.1, 0.1);
      cairo_set_line_width(cr, 3.0);
      cairo_move_to(cr, f.x(in.segment.a.x()), f.y(in.segment.a.y()));
      cairo_line_to(cr, f.x(in.segment.b.x()), f.y(in.segment.b.y()));
      cairo_stroke(cr);
      continue;
    }
    if (mark == InterfaceMark::none)
      continue;
    if (pic.marks.empty() && in.joint_material >= 0 &&
        m.joint_materials[in.joint_material].kind == JointMaterial::Kind::continuum)
      continue;
    const Vec2 a = moved(m, in.block_i, in.segment.a, pic.u, magnify);
    const Vec2 b = moved(m, in.block_i, in.segment.b, pic.u, magnify);
    switch (mark) {
      case InterfaceMark::slipping:
        cairo_set_source_rgb(cr, 0.85, 0.1, 0.1);
        cairo_set_line_width(cr, 3.0);
        break;
      case InterfaceMark::opening:
        cairo_set_source_rgb(cr, 0.1, 0.3, 0.9);
        cairo_set_line_width(cr, 3.0);
        break;
      default:
        cairo_set_source_rgb(cr, 0.2, 0.2, 0.2);
        cairo_set_line_width(cr, 1.2);
        break;
    }
    cairo_move_to(cr, f.x(a.x()), f.y(a.y()));
    cairo_line_to(cr, f.x(b.x()), f.y(b.y()));
    cairo_stroke(cr);
  }
  // Each bolt standing as a thin line from its head to its far end, each moving with its block;
  // then its springs in colour.
  for (std::size_t k = 0; k < pic.bolt_use.size(); ++k) {
    const BoltSpring& s = m.bolt_springs[k];
    const bool first = k == 0 || m.bolt_springs[k - 1].bolt != s.bolt;
    if (!first || std::isnan(pic.bolt_use[k]))
      continue;
    std::size_t last = k;
    while (last + 1 < m.bolt_springs.size() && m.bolt_springs[last + 1].bolt == s.bolt)
      ++last;
    const Bolt& bolt = m.bolts[static_cast<std::size_t>(s.bolt)];
    const Vec2 a = moved(m, s.block_a, bolt.from, pic.u, magnify);
    const Vec2 b = moved(m, m.bolt_springs[last].block_b, bolt.to, pic.u, magnify);
    cairo_set_source_rgb(cr, 0.15, 0.15, 0.15);
    cairo_set_line_width(cr, 1.0);
    cairo_move_to(cr, f.x(a.x()), f.y(a.y()));
    cairo_line_to(cr, f.x(b.x()), f.y(b.y()));
    cairo_stroke(cr);
  }
  for (std::size_t k = 0; k < pic.bolt_use.size(); ++k) {
    if (std::isnan(pic.bolt_use[k]))
      continue;
    const BoltSpring& s = m.bolt_springs[k];
    const double use = std::clamp(pic.bolt_use[k], 0.0, 1.0);
    const Vec2 a = moved(m, s.block_a, s.a, pic.u, magnify);
    const Vec2 b = moved(m, s.block_b, s.b, pic.u, magnify);
    cairo_set_source_rgb(cr, 0.1 + 0.8 * use, 0.6 * (1.0 - use), 0.1);
    cairo_set_line_width(cr, 1.5 + 2.0 * use);
    if (s.a == s.b) {  // a grouted bolt's spring at a joint: a dot between its blocks' points
      const Vec2 c = 0.5 * (a + b);
      cairo_arc(cr, f.x(c.x()), f.y(c.y()), 3.0 + 3.0 * use, 0.0, 2.0 * M_PI);
      cairo_fill(cr);
      continue;
    }
    cairo_move_to(cr, f.x(a.x()), f.y(a.y()));
    cairo_line_to(cr, f.x(b.x()), f.y(b.y()));
    cairo_stroke(cr);
  }
  draw_water_surface(cr, pic.water_surface, f);
  cairo_set_source_rgb(cr, 0, 0, 0);
  cairo_select_font_face(cr, "sans-serif", CAIRO_FONT_SLANT_NORMAL, CAIRO_FONT_WEIGHT_NORMAL);
  cairo_set_font_size(cr, 14);
  cairo_move_to(cr, kMargin, kTitle - 8);
  cairo_show_text(cr, pic.title.c_str());
  if (!pic.marks.empty()) {
    cairo_set_font_size(cr, 12);
    const char* legend = "red: joint slipping   blue: joint opening   black: support";
    cairo_text_extents_t e;
    cairo_text_extents(cr, legend, &e);
    cairo_move_to(cr, width - kMargin - e.width, kTitle - 8);
    cairo_show_text(cr, legend);
  }
  // The footer: a scale bar, the magnification, and the materials where there are several.
  cairo_set_font_size(cr, 12);
  const double base = f.height - 10.0;
  const double bar = scale_bar_length((f.box.hi - f.box.lo).x());
  cairo_set_line_width(cr, 2.0);
  cairo_move_to(cr, kMargin, base - 4);
  cairo_line_to(cr, kMargin + bar * f.scale, base - 4);
  cairo_stroke(cr);
  char text[64];
  std::snprintf(text, sizeof text, "%g m", bar);
  cairo_move_to(cr, kMargin + bar * f.scale + 8, base);
  cairo_show_text(cr, text);
  double x = kMargin + bar * f.scale + 80;
  if (magnify > 0.0) {
    std::snprintf(text, sizeof text, "displacements x %.3g", magnify);
    cairo_move_to(cr, x, base);
    cairo_show_text(cr, text);
    cairo_text_extents_t e;
    cairo_text_extents(cr, text, &e);
    x += e.x_advance + 30;
  }
  if (!pic.bolt_use.empty()) {
    cairo_set_source_rgb(cr, 0.1, 0.6, 0.1);
    cairo_set_line_width(cr, 2.0);
    cairo_move_to(cr, x, base - 5);
    cairo_line_to(cr, x + 14, base - 5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0.9, 0.0, 0.1);
    cairo_set_line_width(cr, 3.5);
    cairo_move_to(cr, x + 16, base - 5);
    cairo_line_to(cr, x + 30, base - 5);
    cairo_stroke(cr);
    cairo_set_source_rgb(cr, 0, 0, 0);
    const char* legend = "bolt force: 0 to capacity";
    cairo_move_to(cr, x + 36, base);
    cairo_show_text(cr, legend);
    cairo_text_extents_t e;
    cairo_text_extents(cr, legend, &e);
    x += 36 + e.x_advance + 30;
  }
  if (m.block_materials.size() > 1)
    for (std::size_t k = 0; k < m.block_materials.size(); ++k) {
      const double* fill = kMaterialColours[k % kColours];
      cairo_rectangle(cr, x, base - 11, 12, 12);
      cairo_set_source_rgb(cr, fill[0], fill[1], fill[2]);
      cairo_fill_preserve(cr);
      cairo_set_source_rgb(cr, 0.35, 0.3, 0.25);
      cairo_set_line_width(cr, 0.6);
      cairo_stroke(cr);
      cairo_set_source_rgb(cr, 0, 0, 0);
      cairo_move_to(cr, x + 16, base);
      cairo_show_text(cr, m.block_materials[k].name.c_str());
      cairo_text_extents_t e;
      cairo_text_extents(cr, m.block_materials[k].name.c_str(), &e);
      x += 16 + e.x_advance + 20;
    }
}

}  // namespace

double scale_bar_length(double width) {
  if (!(width > 0.0))
    return 1.0;
  const double most = width / 5.0;
  const double decade = std::pow(10.0, std::floor(std::log10(most)));
  for (const double f : {5.0, 2.0, 1.0})
    if (f * decade <= most * (1.0 + 1e-12))
      return f * decade;
  return decade;
}

double displacement_magnification(const Model& model, const Eigen::VectorXd& u, double fraction,
                                  double size, const std::vector<char>& present) {
  if (u.size() == 0)
    return 0.0;
  double largest = 0.0;
  for (int b = 0; b < model.n_blocks(); ++b)
    if (present.empty() || present[static_cast<std::size_t>(b)] != 0)
      for (const Vec2& v : model.blocks[b].polygon.vertices)
        largest =
            std::max(largest, (block_Q(model.blocks[b].centroid, v) * u.segment<6>(6 * b)).norm());
  return largest > 0.0 ? fraction * size / largest : 0.0;
}

void write_block_picture(const Model& model, const BlockPicture& pic,
                         const std::filesystem::path& stem) {
  Frame f;
  for (const Block& b : model.blocks)
    f.box.add(bbox_of(b.polygon));
  const double grow = 0.08 * f.box.diagonal();  // room for the displaced blocks
  f.box.lo -= Vec2(grow, grow);
  f.box.hi += Vec2(grow, grow);
  const Vec2 size = f.box.hi - f.box.lo;
  const double width = pic.width_px;
  f.scale = (width - 2 * kMargin) / size.x();
  const double height = std::ceil(size.y() * f.scale + 2 * kMargin + kTitle + kFooter);
  f.height = height;
  const std::filesystem::path png = stem.string() + ".png";
  const std::filesystem::path svg = stem.string() + ".svg";
  cairo_surface_t* image =
      cairo_image_surface_create(CAIRO_FORMAT_RGB24, pic.width_px, int(height));
  cairo_t* cr = cairo_create(image);
  draw(cr, model, pic, f, width);
  cairo_destroy(cr);
  const cairo_status_t written = cairo_surface_write_to_png(image, png.c_str());
  cairo_surface_destroy(image);
  if (written != CAIRO_STATUS_SUCCESS)
    throw std::runtime_error("cannot write " + png.string());
  cairo_surface_t* vector = cairo_svg_surface_create(svg.c_str(), width, height);
  cr = cairo_create(vector);
  draw(cr, model, pic, f, width);
  cairo_destroy(cr);
  cairo_surface_finish(vector);
  const bool ok = cairo_surface_status(vector) == CAIRO_STATUS_SUCCESS;
  cairo_surface_destroy(vector);
  if (!ok)
    throw std::runtime_error("cannot write " + svg.string());
}

}  // namespace bimrock
