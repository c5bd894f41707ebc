#include <bimrock/model/block_generation.hpp>

#include <algorithm>
#include <cmath>

#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/model/errors.hpp>
#include <bimrock/model/limits.hpp>

namespace bimrock {

std::string GeneratedBlocks::joint_between(int i, int j) const {
  const int a = parent[static_cast<std::size_t>(i)];
  const int b = parent[static_cast<std::size_t>(j)];
  if (a == b)
    return "";  // cells of one block: intact rock
  const auto it = joint_between_parents.find({std::min(a, b), std::max(a, b)});
  return it == joint_between_parents.end() ? std::string() : it->second;
}

namespace {

// The line of an item, or of its nearest listed ancestor ("domain.joint_sets[0].spacing" ->
// "domain.joint_sets[0]" -> "domain").
int line_of(const DomainSpec& spec, std::string item) {
  while (!item.empty()) {
    if (const auto it = spec.lines.find(item); it != spec.lines.end())
      return it->second;
    const std::size_t cut = item.find_last_of(".[");
    if (cut == std::string::npos)
      break;
    item.resize(cut);
  }
  return spec.source.line;
}

// Exact cutting places every corner exactly, but corners that joints make nearly meet (closer
// than the model's length tolerance) round to neighbouring doubles. The second of two such
// corners is dropped: the block moves by less than the tolerance, and interface detection, which
// works to the same tolerance, still pairs it with its neighbours. A block whose corners all lie
// within the tolerance of one or two points (a face of positive exact area, e.g. 1e-13 m^2, thinner
// than the tolerance) keeps fewer than 3 vertices: it holds no rock, and the caller leaves it out.
Polygon without_short_edges(const Polygon& p, double tol) {
  Polygon out;
  for (const Vec2& v : p.vertices) {
    if (out.vertices.empty() || (v - out.vertices.back()).norm() > tol)
      out.vertices.push_back(v);
  }
  while (out.vertices.size() > 1 && (out.vertices.back() - out.vertices.front()).norm() <= tol)
    out.vertices.pop_back();
  return out;
}

// The number of blocks cutting `spec` yields, estimated from its traces before they are
// generated: by Euler's formula, about one block per trace and per crossing, and two sets of
// total trace lengths La, Lb at angle theta spread over an area A cross about
// La Lb |sin theta| / A times. Throws InputError when the traces or blocks exceed `limits`.
void check_generation_limits(const DomainSpec& spec, const std::string& file,
                             const CaseLimits& limits) {
  const BBox box = bbox_of(spec.domain);
  if (box.empty())
    return;
  double traces = static_cast<double>(spec.joints.size());
  std::vector<TraceEstimate> estimates;
  std::vector<double> areas;
  for (std::size_t s = 0; s < spec.joint_sets.size(); ++s) {
    const JointSet& set = spec.joint_sets[s];
    validate(set, "joint_sets[" + std::to_string(s) + "]");
    estimates.push_back(estimate_traces(set, box));
    const double w = box.diagonal() + 2.0 * trace_margin(box, set);
    areas.push_back(w * w);
    traces += estimates.back().traces;
    if (traces > limits.joint_traces) {
      const std::string item = "domain.joint_sets[" + std::to_string(s) + "]";
      throw InputError(file, line_of(spec, item), item,
                       limit_message(traces, limits.joint_traces, "joint_traces", "joint traces",
                                     "check spacing, trace_length and gap"));
    }
  }
  double blocks = 1.0 + traces;
  for (std::size_t a = 0; a < estimates.size(); ++a) {
    for (std::size_t b = a + 1; b < estimates.size(); ++b) {
      const double angle = (spec.joint_sets[a].dip_deg - spec.joint_sets[b].dip_deg) * M_PI / 180;
      blocks += estimates[a].length * estimates[b].length * std::abs(std::sin(angle)) /
                std::max(areas[a], areas[b]);
    }
  }
  // Named: the set with the most traces (the one whose spacing or traces are likely mistyped).
  std::string item = "domain";
  double most = 0.0;
  for (std::size_t s = 0; s < estimates.size(); ++s) {
    if (estimates[s].traces > most) {
      most = estimates[s].traces;
      item = "domain.joint_sets[" + std::to_string(s) + "]";
    }
  }
  std::string advice = "check the spacings, trace lengths and gaps";
  if (spec.subdivision) {
    const double size = spec.subdivision->target_size;
    const double area = (box.hi.x() - box.lo.x()) * (box.hi.y() - box.lo.y());
    const double cells = area / (size * size);
    if (area > 2.0 * size * size) {
      if (cells > blocks) {  // the subdivision is named when its cells outnumber the cuts
        item = "domain.subdivision";
        advice = "check subdivision.size (about one cell per size^2 of the domain)";
      }
      blocks += cells;
    }
  }
  if (blocks > limits.blocks) {
    throw InputError(file, line_of(spec, item), item,
                     limit_message(blocks, limits.blocks, "blocks", "blocks", advice));
  }
}

}  // namespace

GeneratedBlocks generate_blocks(const DomainSpec& spec, const std::string& file,
                                const CaseLimits& limits) {
  GeneratedBlocks out;
  try {
    validate(spec.domain);
    check_generation_limits(spec, file, limits);
    const std::vector<JointTrace> traces =
        generate_traces(spec.joint_sets, spec.joints, bbox_of(spec.domain));
    CutOptions options;
    options.min_block_area =
        spec.min_block_area.value_or(suggested_min_block_area(spec.joint_sets));
    const BlockCut cut = cut_blocks(spec.domain, traces, options);
    out.stats = cut.stats;

    // The material along each pair of touching cut blocks: the kind covering most of their edge.
    std::map<std::pair<int, int>, std::map<std::string, double>> lengths;
    for (const CutEdge& e : cut.edges) {
      if (e.left < 0 || e.right < 0)
        continue;
      const std::string material = e.kind == EdgeKind::joint && e.trace >= 0
                                       ? traces[static_cast<std::size_t>(e.trace)].material
                                       : std::string();
      const double length = (cut.vertices[static_cast<std::size_t>(e.b)] -
                             cut.vertices[static_cast<std::size_t>(e.a)])
                                .norm();
      lengths[{std::min(e.left, e.right), std::max(e.left, e.right)}][material] += length;
    }
    for (const auto& [pair, by_material] : lengths) {
      const auto longest =
          std::max_element(by_material.begin(), by_material.end(),
                           [](const auto& a, const auto& b) { return a.second < b.second; });
      out.joint_between_parents[pair] = longest->first;
    }

    const double tol = 2.0 * model_tolerance(bbox_of(spec.domain));
    std::vector<Polygon> polygons = block_polygons(cut);
    for (Polygon& p : polygons)
      p = without_short_edges(p, tol);
    std::vector<VoronoiCell> cells;
    if (spec.subdivision) {
      const double size = spec.subdivision->target_size;
      cells = subdivide_large_blocks(polygons, 2.0 * size * size, *spec.subdivision);
    } else {
      for (std::size_t k = 0; k < polygons.size(); ++k)
        cells.push_back({polygons[k], static_cast<int>(k)});
    }
    std::vector<int> cells_of(polygons.size(), 0);
    for (VoronoiCell& c : cells) {
      // A cut block thinner than the tolerance, or a clipped Voronoi cell collapsed to a segment,
      // holds no rock, so it is left out (and counted). Zero area is judged as the model's
      // polygon check judges it: against tol times the polygon's size.
      c.polygon = without_short_edges(c.polygon, tol);
      if (c.polygon.size() < 3 ||
          std::abs(signed_area(c.polygon)) <= tol * bbox_of(c.polygon).diagonal()) {
        ++out.degenerate_cells;
        continue;
      }
      const CutBlock& parent = cut.blocks[static_cast<std::size_t>(c.parent)];
      const std::string& material =
          parent.zone >= 0 ? spec.domain.zones[static_cast<std::size_t>(parent.zone)].material
                           : spec.material;
      const int k = static_cast<int>(out.blocks.size());
      out.blocks.push_back(
          {c.polygon, material, {spec.source.line, "domain block " + std::to_string(k)}});
      out.parent.push_back(c.parent);
      ++cells_of[static_cast<std::size_t>(c.parent)];
    }
    out.subdivided = static_cast<int>(
        std::count_if(cells_of.begin(), cells_of.end(), [](int n) { return n > 1; }));
  } catch (const GeometryError& e) {
    throw InputError(file, line_of(spec, e.item()), e.item(), e.message());
  }
  if (out.blocks.empty())
    throw InputError(file, spec.source, "the domain yields no block");
  return out;
}

}  // namespace bimrock
