#include <bimrock/geometry/voronoi_subdivision.hpp>

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <bimrock/geometry/block_cutter.hpp>
#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/seeded_random.hpp>

namespace bimrock {
namespace {

// Voronoi edges only need to be consistent, not exact: each circumcentre is computed once per
// Delaunay triangle and shared by the three edges that meet there; the exact block cutter then
// clips them to the block.
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Delaunay = CGAL::Delaunay_triangulation_2<K>;

void check(const VoronoiOptions& o) {
  if (!(o.target_size > 0.0) || !std::isfinite(o.target_size))
    throw GeometryError("voronoi.target_size", "must be positive");
  if (!(o.jitter >= 0.0 && o.jitter <= 1.0))
    throw GeometryError("voronoi.jitter", "must lie between 0 and 1");
  if (!(o.min_cell_fraction >= 0.0 && o.min_cell_fraction < 1.0))
    throw GeometryError("voronoi.min_cell_fraction", "must lie in [0, 1)");
}

// The two vertices of a convex polygon farthest apart (its diameter's ends).
std::pair<Vec2, Vec2> farthest_vertices(const Polygon& block) {
  std::pair<Vec2, Vec2> ends{block.vertices.front(), block.vertices.front()};
  double longest = -1.0;
  for (const Vec2& a : block.vertices)
    for (const Vec2& b : block.vertices)
      if ((b - a).squaredNorm() > longest) {
        longest = (b - a).squaredNorm();
        ends = {a, b};
      }
  return ends;
}

// Cuts across a long thin block (a sliver of a convex partition fanning from a far corner, which
// holds fewer grid seeds than its length needs, or none): straight lines normal to its diameter,
// about h apart, split it into convex pieces about h long. Seeds along so thin a block would be
// nearly collinear, their Voronoi vertices far away or at infinity.
std::vector<JointTrace> transverse_cuts(const Polygon& block, double h) {
  const auto [a, b] = farthest_vertices(block);
  const double length = (b - a).norm();
  const auto pieces = static_cast<int>(std::round(length / h));
  const Vec2 along = (b - a) / length;
  const Vec2 across(-along.y(), along.x());
  const double reach = bbox_of(block).diagonal();
  std::vector<JointTrace> cuts;
  for (int i = 1; i < pieces; ++i) {
    const Vec2 p = a + along * (length * i / pieces);
    cuts.push_back({{p - reach * across, p + reach * across}, -1, i - 1, ""});
  }
  return cuts;
}

std::vector<Vec2> seed_points(const Polygon& block, const VoronoiOptions& o, SeededRandom& rng) {
  const BBox box = bbox_of(block);
  const double inset = -model_tolerance(box);  // strictly inside, not on a side
  const double h = o.target_size;
  std::vector<Vec2> seeds;
  if (o.pattern == SeedPattern::jittered_grid) {
    const Vec2 size = box.hi - box.lo;
    const auto nx = static_cast<int>(std::max(1.0, std::ceil(size.x() / h)));
    const auto ny = static_cast<int>(std::max(1.0, std::ceil(size.y() / h)));
    const Vec2 start = box.lo + 0.5 * (size - Vec2(nx * h, ny * h));  // grid centred on the box
    const double move = 0.5 * o.jitter * h;
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        const double dx = rng.uniform(-move, move);  // drawn for every cell: reproducible
        const double dy = rng.uniform(-move, move);
        const Vec2 p = start + Vec2((i + 0.5) * h + dx, (j + 0.5) * h + dy);
        if (contains(block, p, inset))
          seeds.push_back(p);
      }
    }
    return seeds;
  }
  const auto n = static_cast<std::size_t>(std::max(1.0, std::round(signed_area(block) / (h * h))));
  for (std::size_t attempt = 0; seeds.size() < n && attempt < 100 * n; ++attempt) {
    // y before x, in statements of their own: a seed's blocks depend on the order of the draws,
    // which the order of evaluating a call's arguments would leave to the compiler.
    const double y = rng.uniform(box.lo.y(), box.hi.y());
    const double x = rng.uniform(box.lo.x(), box.hi.x());
    const Vec2 p(x, y);
    if (contains(block, p, inset))
      seeds.push_back(p);
  }
  return seeds;
}

// Voronoi edges of the seeds, rays and lines cut off far outside the block.
std::vector<JointTrace> voronoi_edges(const std::vector<Vec2>& seeds, const BBox& box) {
  Delaunay dt;
  for (const Vec2& s : seeds)
    dt.insert(K::Point_2(s.x(), s.y()));
  const double far = box.diagonal();
  const K::Iso_rectangle_2 clip(box.lo.x() - far, box.lo.y() - far, box.hi.x() + far,
                                box.hi.y() + far);
  std::vector<JointTrace> edges;
  const auto add = [&](const K::Segment_2& s) {
    edges.push_back({{{s.source().x(), s.source().y()}, {s.target().x(), s.target().y()}},
                     -1,
                     static_cast<int>(edges.size()),
                     ""});
  };
  const auto add_clipped = [&](const auto& infinite) {
    const auto x = CGAL::intersection(clip, infinite);
    if (!x)
      return;
    if (const auto* s = boost::get<K::Segment_2>(&*x))
      add(*s);
  };
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
    const CGAL::Object o = dt.dual(*e);
    if (const auto* s = CGAL::object_cast<K::Segment_2>(&o))
      add(*s);
    else if (const auto* r = CGAL::object_cast<K::Ray_2>(&o))
      add_clipped(*r);
    else if (const auto* l = CGAL::object_cast<K::Line_2>(&o))
      add_clipped(*l);
  }
  // The triangulation's storage order depends on its point-location walk, not only on the
  // seeds; a canonical order makes the cut (down to the last bit) a function of the seeds.
  const auto key = [](const JointTrace& t) {
    return std::make_tuple(t.segment.a.x(), t.segment.a.y(), t.segment.b.x(), t.segment.b.y());
  };
  for (JointTrace& t : edges)
    if (std::make_pair(t.segment.b.x(), t.segment.b.y()) <
        std::make_pair(t.segment.a.x(), t.segment.a.y()))
      std::swap(t.segment.a, t.segment.b);
  std::sort(edges.begin(), edges.end(),
            [&](const JointTrace& p, const JointTrace& q) { return key(p) < key(q); });
  for (std::size_t k = 0; k < edges.size(); ++k)
    edges[k].joint = static_cast<int>(k);
  return edges;
}

}  // namespace

std::vector<VoronoiCell> voronoi_subdivision(const Polygon& block, int parent,
                                             const VoronoiOptions& options) {
  check(options);
  const BBox box = bbox_of(block);
  const PolygonCheck c = check_convex_polygon(block, model_tolerance(box));
  if (c.defect != PolygonDefect::none)
    throw GeometryError("blocks[" + std::to_string(parent) + "]", describe(c));
  SeededRandom rng(derive_seed(options.seed, static_cast<std::uint64_t>(parent)));
  const std::vector<Vec2> seeds = seed_points(block, options, rng);
  const auto [end_a, end_b] = farthest_vertices(block);
  const bool thin =
      static_cast<double>(seeds.size()) < (end_b - end_a).norm() / options.target_size - 1.0;
  if (!thin && seeds.size() < 2)
    return {{block, parent}};
  const std::vector<JointTrace> edges =
      thin ? transverse_cuts(block, options.target_size) : voronoi_edges(seeds, box);
  CutOptions cut_options;
  cut_options.min_block_area =
      options.min_cell_fraction * options.target_size * options.target_size;
  const BlockCut cut = cut_blocks(Domain{block, {}, {}}, edges, cut_options);
  std::vector<VoronoiCell> cells;
  cells.reserve(cut.blocks.size());
  for (const CutBlock& b : cut.blocks)
    cells.push_back({b.polygon, parent});
  return cells;
}

std::vector<VoronoiCell> subdivide_large_blocks(std::span<const Polygon> blocks, double max_area,
                                                const VoronoiOptions& options) {
  std::vector<VoronoiCell> cells;
  for (std::size_t k = 0; k < blocks.size(); ++k) {
    const int parent = static_cast<int>(k);
    // Small enough, and not longer than twice the side of the largest square kept whole (a
    // sliver of small area can span the domain), unless smaller than the smallest cell kept.
    const double area = signed_area(blocks[k]);
    const double h = options.target_size;
    const auto [a, b] = farthest_vertices(blocks[k]);
    if (area <= max_area && ((b - a).norm() <= 2.0 * std::sqrt(max_area) ||
                             area <= options.min_cell_fraction * h * h)) {
      cells.push_back({blocks[k], parent});
      continue;
    }
    std::vector<VoronoiCell> part = voronoi_subdivision(blocks[k], parent, options);
    cells.insert(cells.end(), part.begin(), part.end());
  }
  return cells;
}

}  // namespace bimrock
