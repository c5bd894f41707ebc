#include <bimrock/model/block_selector.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include <bimrock/geometry/geometry_error.hpp>
#include <bimrock/geometry/outline.hpp>

namespace bimrock {
namespace {

bool finite(const Vec2& p) {
  return std::isfinite(p.x()) && std::isfinite(p.y());
}

}  // namespace

std::vector<int> select_blocks(const Model& model, const BlockSelector& sel) {
  const auto fail = [&](const std::string& message) {
    throw InputError(model.source_file, sel.source, message);
  };
  std::vector<int> picked;
  const auto pick_if = [&](const auto& test) {
    for (int b = 0; b < model.n_blocks(); ++b) {
      if (test(model.blocks[static_cast<std::size_t>(b)]))
        picked.push_back(b);
    }
  };
  switch (sel.kind) {
    case BlockSelector::Kind::region:
      try {
        validate_outline(sel.region, sel.source.item);
      } catch (const GeometryError& e) {
        fail(e.message());
      }
      {
        const BBox box = bbox_of(sel.region);  // a cheap test first: most blocks lie outside
        pick_if([&](const Block& b) {
          return box.contains(b.centroid, model.tolerance) &&
                 outline_contains(sel.region, b.centroid, model.tolerance);
        });
      }
      break;
    case BlockSelector::Kind::box:
      if (!finite(sel.box.lo) || !finite(sel.box.hi))
        fail("the box's corners must be finite points");
      if (sel.box.lo.x() > sel.box.hi.x() || sel.box.lo.y() > sel.box.hi.y())
        fail("the first corner must be the lower-left one: [[xmin, ymin], [xmax, ymax]]");
      pick_if([&](const Block& b) { return sel.box.contains(b.centroid, model.tolerance); });
      break;
    case BlockSelector::Kind::material: {
      const auto& materials = model.block_materials;
      const auto named =
          std::find_if(materials.begin(), materials.end(),
                       [&](const BlockMaterial& m) { return m.name == sel.material; });
      if (named == materials.end())
        fail("unknown material '" + sel.material + "'");
      const int m = static_cast<int>(named - materials.begin());
      pick_if([&](const Block& b) { return b.material == m; });
      break;
    }
    case BlockSelector::Kind::list:
      for (const int b : sel.blocks) {
        if (b < 0 || b >= model.n_blocks())
          fail("there is no block " + std::to_string(b) + ": the model's " +
               std::to_string(model.n_blocks()) + " blocks are numbered from 0 to " +
               std::to_string(model.n_blocks() - 1));
      }
      picked = sel.blocks;
      std::sort(picked.begin(), picked.end());
      picked.erase(std::unique(picked.begin(), picked.end()), picked.end());
      break;
  }
  return picked;
}

}  // namespace bimrock
