#include <bimrock/geometry/block_cutter.hpp>

#include <cmath>
#include <stdexcept>
#include <utility>

#include <bimrock/geometry/convex_partition.hpp>
#include <bimrock/geometry/cut_arrangement.hpp>
#include <bimrock/geometry/face_cuts.hpp>
#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/sliver_merge.hpp>

namespace bimrock {
namespace {

using cut::Arrangement;
using cut::Face_handle;
using cut::Halfedge_handle;

// Builds the blocks and edges from a fully cut arrangement (every inside face convex).
class Extractor {
 public:
  Extractor(Arrangement& arr, double tol, BlockCut& out) : arr_(arr), tol_(tol), out_(out) {}

  void run() {
    for (auto v = arr_.vertices_begin(); v != arr_.vertices_end(); ++v)
      v->data() = -1;
    for (auto h = arr_.halfedges_begin(); h != arr_.halfedges_end(); ++h)
      h->data() = -1;
    for (auto f = arr_.faces_begin(); f != arr_.faces_end(); ++f)
      if (f->data().inside)
        add_block(f);
    add_edges();
  }

 private:
  int vertex_id(cut::Vertex_handle v) {
    if (v->data() < 0) {
      v->data() = static_cast<int>(out_.vertices.size());
      out_.vertices.push_back(cut::to_vec2(v->point()));
    }
    return v->data();
  }

  void add_block(Face_handle f) {
    cut::find_corners(f, corners_);
    if (corners_.reflex_deviation > tol_)
      throw std::logic_error("block cutter: a face is not convex");
    const int id = static_cast<int>(out_.blocks.size());
    CutBlock b;
    b.face = f->data().region;
    b.zone = cut::first_zone(f->data().zones);
    for (std::size_t i : corners_.corner_pos) {
      b.vertex_ids.push_back(vertex_id(corners_.cycle[i]->source()));
      b.polygon.vertices.push_back(out_.vertices[b.vertex_ids.back()]);
    }
    for (const Halfedge_handle h : corners_.cycle)
      h->data() = id;
    out_.blocks.push_back(std::move(b));
  }

  void add_edges() {
    for (auto e = arr_.edges_begin(); e != arr_.edges_end(); ++e) {
      const Halfedge_handle h = e;
      const int left = h->data();
      const int right = h->twin()->data();
      if (left < 0 && right < 0)
        continue;
      const cut::CurveTag& tag = h->curve().data();
      EdgeKind kind = EdgeKind::rock_bridge;
      if (left < 0 || right < 0)
        kind = EdgeKind::boundary;
      else if (tag.trace >= 0)
        kind = EdgeKind::joint;
      else if (tag.zones != 0)
        kind = EdgeKind::zone_boundary;
      else if (tag.partition)
        kind = EdgeKind::partition;
      out_.edges.push_back(
          {vertex_id(h->source()), vertex_id(h->target()), left, right, kind, tag.trace});
    }
  }

  Arrangement& arr_;
  double tol_;
  BlockCut& out_;
  cut::FaceCorners corners_;  // reused from face to face
};

void check_traces(std::span<const JointTrace> traces) {
  for (std::size_t t = 0; t < traces.size(); ++t) {
    const Segment& s = traces[t].segment;
    if (!std::isfinite(s.a.x()) || !std::isfinite(s.a.y()) || !std::isfinite(s.b.x()) ||
        !std::isfinite(s.b.y()))
      throw GeometryError("traces[" + std::to_string(t) + "]", "an end point is not finite");
  }
}

}  // namespace

BlockCut cut_blocks(const Domain& domain, std::span<const JointTrace> traces,
                    const CutOptions& options) {
  validate(domain);
  check_traces(traces);
  BlockCut out;
  Arrangement arr;
  cut::build(arr, domain, traces);
  for (const JointTrace& t : traces)
    out.stats.n_traces += t.segment.a != t.segment.b ? 1 : 0;
  out.stats.n_rock_bridges = cut::extend_dangling_ends(arr);
  out.stats.n_hole_cuts = cut::make_faces_simple(arr);
  out.stats.n_faces = cut::number_regions(arr);
  out.stats.n_partitioned_faces = cut::partition_faces(arr, options.max_optimal_partition_vertices);
  const double tol = model_tolerance(bbox_of(domain));
  const cut::SliverCounts slivers = cut::merge_slivers(arr, options.min_block_area, tol);
  out.stats.n_slivers_merged = slivers.merged;
  out.stats.n_slivers_kept = slivers.kept;
  out.stats.n_joint_edges_removed = slivers.joint_edges_removed;
  // A merge of two convex faces is convex by construction; where round-off hides a reflex turn
  // (slivers 1e-15 wide), partition again rather than hand out a non-convex block.
  out.stats.n_partitioned_faces +=
      cut::partition_faces(arr, options.max_optimal_partition_vertices, tol);
  Extractor(arr, tol, out).run();
  for (const CutBlock& b : out.blocks)
    out.stats.n_small_blocks += signed_area(b.polygon) < options.min_block_area ? 1 : 0;
  return out;
}

std::vector<Polygon> block_polygons(const BlockCut& cut) {
  std::vector<Polygon> out;
  out.reserve(cut.blocks.size());
  for (const CutBlock& b : cut.blocks)
    out.push_back(b.polygon);
  return out;
}

}  // namespace bimrock
