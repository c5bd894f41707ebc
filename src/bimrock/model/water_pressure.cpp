#include <bimrock/model/water_pressure.hpp>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include <bimrock/model/errors.hpp>

namespace bimrock {
namespace {

/// A block face water may push on: the outward normal is the block's.
struct WetFace {
  int block;
  Segment segment;
  Vec2 outward_normal;
};

/// Every face in contact with water: the outline (supports included) and both faces of every
/// joint. Continuum interfaces are cuts through intact rock, which is impermeable.
std::vector<WetFace> wet_faces(const Model& model) {
  std::vector<WetFace> out;
  for (const BoundaryEdge& e : model.boundary)
    out.push_back({e.polygon, e.segment, e.outward_normal});
  for (const Interface& f : model.interfaces) {
    if (f.is_support())
      continue;  // its block's face is part of the outline
    if (model.joint_materials[f.joint_material].kind == JointMaterial::Kind::continuum)
      continue;
    out.push_back({f.block_i, f.segment, f.normal});
    out.push_back({f.block_j, f.segment, -f.normal});
  }
  return out;
}

/// The interval [s0, s1] of the face's parameter on which it lies on the pressure line (its
/// ends within tol of the line's and between the line's ends), if it is longer than tol.
std::optional<std::pair<double, double>> on_line(const Segment& face, const PressureLineSpec& line,
                                                 double tol) {
  const Vec2 d = line.to - line.from;
  const double length = d.norm();
  const auto off = [&](const Vec2& p) { return std::abs(cross(d, p - line.from)) / length; };
  if (off(face.a) > tol || off(face.b) > tol)
    return std::nullopt;
  const double ua = (face.a - line.from).dot(d) / (length * length);
  const double ub = (face.b - line.from).dot(d) / (length * length);
  const double face_length = face.length();
  double s0 = (0.0 - ua) / (ub - ua);  // ub != ua: the face is longer than tol and on the line
  double s1 = (1.0 - ua) / (ub - ua);
  if (s0 > s1)
    std::swap(s0, s1);
  s0 = s0 * face_length < tol ? 0.0 : s0;
  s1 = (1.0 - s1) * face_length < tol ? 1.0 : s1;
  if ((s1 - s0) * face_length <= tol)
    return std::nullopt;
  return std::pair{s0, s1};
}

double line_pressure(const PressureLineSpec& line, const Vec2& p) {
  const Vec2 d = line.to - line.from;
  const double u = std::clamp((p - line.from).dot(d) / d.squaredNorm(), 0.0, 1.0);
  return line.pressure_from + u * (line.pressure_to - line.pressure_from);
}

/// Pieces of one face: the parts on a pressure line take its pressure, the rest the phreatic
/// surface's, cut below each point of the surface and where the surface crosses the face.
void add_pieces(const WetFace& face, const WaterSpec& water, double tol,
                std::vector<char>& line_used, std::vector<PressureFace>& out) {
  const Segment& s = face.segment;
  std::vector<double> cuts = {0.0, 1.0};
  std::vector<std::optional<std::pair<double, double>>> covered(water.lines.size());
  for (std::size_t k = 0; k < water.lines.size(); ++k) {
    covered[k] = on_line(s, water.lines[k], tol);
    if (covered[k]) {
      line_used[k] = 1;
      cuts.push_back(covered[k]->first);
      cuts.push_back(covered[k]->second);
    }
  }
  if (s.b.x() != s.a.x()) {  // the surface's points above the face (x increasing: a search)
    const auto x_of = [](const Vec2& v, double x) { return v.x() < x; };
    const auto first = std::lower_bound(water.surface.begin(), water.surface.end(),
                                        std::min(s.a.x(), s.b.x()), x_of);
    for (auto v = first; v != water.surface.end() && v->x() < std::max(s.a.x(), s.b.x()); ++v)
      cuts.push_back((v->x() - s.a.x()) / (s.b.x() - s.a.x()));
  }
  std::sort(cuts.begin(), cuts.end());
  cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());

  const auto emit = [&](double t0, double t1, double p0, double p1) {
    if (t1 > t0 && (p0 != 0.0 || p1 != 0.0))
      out.push_back({face.block, {s.at(t0), s.at(t1)}, face.outward_normal, p0, p1});
  };
  const auto head = [&](double t) {  // of the phreatic surface above the point [m]
    const Vec2 p = s.at(t);
    return phreatic_height(water.surface, p.x()) - p.y();
  };
  for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
    const double t0 = cuts[c];
    const double t1 = cuts[c + 1];
    const double mid = 0.5 * (t0 + t1);
    const auto line = std::find_if(covered.begin(), covered.end(), [&](const auto& interval) {
      return interval && interval->first <= mid && mid <= interval->second;
    });
    if (line != covered.end()) {
      const PressureLineSpec& l = water.lines[static_cast<std::size_t>(line - covered.begin())];
      emit(t0, t1, line_pressure(l, s.at(t0)), line_pressure(l, s.at(t1)));
    } else if (!water.surface.empty()) {
      // The head is linear between the cuts: keep its positive part.
      const double g0 = head(t0);
      const double g1 = head(t1);
      const double w = water.unit_weight;
      if (g0 >= 0.0 && g1 >= 0.0)
        emit(t0, t1, w * g0, w * g1);
      else if (g0 > 0.0)
        emit(t0, t0 + (t1 - t0) * g0 / (g0 - g1), w * g0, 0.0);
      else if (g1 > 0.0)
        emit(t0 + (t1 - t0) * g0 / (g0 - g1), t1, 0.0, w * g1);
    }
  }
}

}  // namespace

double phreatic_height(std::span<const Vec2> surface, double x) {
  if (x <= surface.front().x())
    return surface.front().y();
  if (x >= surface.back().x())
    return surface.back().y();
  const auto right = std::upper_bound(surface.begin(), surface.end(), x,
                                      [](double value, const Vec2& v) { return value < v.x(); });
  const Vec2& b = *right;
  const Vec2& a = *(right - 1);
  return a.y() + (x - a.x()) / (b.x() - a.x()) * (b.y() - a.y());
}

double phreatic_pressure(std::span<const Vec2> surface, double unit_weight, const Vec2& p) {
  if (surface.empty())
    return 0.0;
  return unit_weight * std::max(0.0, phreatic_height(surface, p.x()) - p.y());
}

std::vector<PressureFace> water_faces(const Model& model, const WaterSpec& water) {
  std::vector<PressureFace> out;
  std::vector<char> line_used(water.lines.size(), 0);
  for (const WetFace& face : wet_faces(model))
    add_pieces(face, water, model.tolerance, line_used, out);
  for (std::size_t k = 0; k < water.lines.size(); ++k) {
    if (!line_used[k]) {
      throw InputError(model.source_file, water.lines[k].source,
                       "lies on no wet block face (a joint, a support or the outline)");
    }
  }
  return out;
}

}  // namespace bimrock
