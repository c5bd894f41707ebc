#include <bimrock/model/stage_blocks.hpp>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>

#include <bimrock/model/block_selector.hpp>

namespace bimrock {
namespace {

constexpr int kNever = -1;

class StageBlocks {
 public:
  StageBlocks(Model& model, const std::vector<StageSpec>& stages)
      : model_(model),
        stages_(stages),
        installed_by_(model.blocks.size(), kNever),
        excavated_by_(model.blocks.size(), kNever) {}

  void resolve() {
    std::vector<std::vector<int>> excavated(stages_.size());
    std::vector<std::vector<int>> installed(stages_.size());
    for (std::size_t k = 0; k < stages_.size(); ++k) {
      excavated[k] = select(k, stages_[k].excavate, "excavate");
      installed[k] = select(k, stages_[k].install, "install");
      // A block some stage installs is absent until then, and is installed once: after an
      // excavation it stays out.
      for (const int b : installed[k]) {
        if (installed_by_[b] != kNever)
          fail(where(k, "install"), describe(b) + " is already installed by " +
                                        stage(installed_by_[b]) + ": a block is installed once");
        installed_by_[b] = static_cast<int>(k);
      }
    }
    present_.resize(model_.blocks.size());
    for (std::size_t b = 0; b < present_.size(); ++b)
      present_[b] = installed_by_[b] == kNever ? 1 : 0;
    auto count = static_cast<std::size_t>(std::count(present_.begin(), present_.end(), 1));
    bool any_excavated = false;
    for (std::size_t k = 0; k < stages_.size(); ++k) {
      check_changes(k, excavated[k], installed[k], count);
      for (const int b : excavated[k]) {
        present_[b] = 0;
        excavated_by_[b] = static_cast<int>(k);
      }
      for (const int b : installed[k])
        present_[b] = 1;
      count = count - excavated[k].size() + installed[k].size();
      any_excavated = any_excavated || !excavated[k].empty();
      check_release(k, any_excavated);
      check_loads(k, count);
      Stage& st = model_.stages[k];
      st.excavated = std::move(excavated[k]);
      st.installed = std::move(installed[k]);
      st.release = stages_[k].release;
    }
  }

 private:
  [[noreturn]] void fail(const SourceRef& ref, const std::string& message) const {
    throw InputError(model_.source_file, ref, message);
  }

  // The item of a stage's selector (key "excavate" or "install"): the selector's own, else the
  // stage's key.
  SourceRef where(std::size_t k, std::string_view key) const {
    const StageSpec& st = stages_[k];
    const std::optional<BlockSelector>& sel = key == "excavate" ? st.excavate : st.install;
    if (sel && !sel->source.item.empty())
      return sel->source;
    return {st.source.line, st.source.item + "." + std::string(key)};
  }

  std::string stage(int k) const {
    const StageSpec& st = stages_[static_cast<std::size_t>(k)];
    return (st.source.item.empty() ? "stage " + std::to_string(k) : st.source.item) + " ('" +
           st.name + "')";
  }

  std::string describe(int b) const {
    const Vec2& c = model_.blocks[static_cast<std::size_t>(b)].centroid;
    std::ostringstream s;
    s << "block " << b << " (centroid (" << c.x() << ", " << c.y() << "))";
    return s.str();
  }

  // Why block b is absent now.
  std::string absence(int b) const {
    if (excavated_by_[b] != kNever)
      return "excavated by " + stage(excavated_by_[b]);
    return "not installed until " + stage(installed_by_[b]) +
           ", as a block some stage installs is absent until then";
  }

  std::vector<int> select(std::size_t k, const std::optional<BlockSelector>& sel,
                          std::string_view key) const {
    if (!sel)
      return {};
    BlockSelector named = *sel;
    named.source = where(k, key);
    std::vector<int> blocks = select_blocks(model_, named);
    if (blocks.empty()) {
      switch (sel->kind) {
        case BlockSelector::Kind::region:
          fail(named.source, "selects no block: no block's centroid lies in the region");
        case BlockSelector::Kind::box:
          fail(named.source, "selects no block: no block's centroid lies in the box");
        case BlockSelector::Kind::material:
          fail(named.source, "selects no block: no block is of material '" + sel->material + "'");
        case BlockSelector::Kind::list:
          fail(named.source, "selects no block: list at least one block index");
      }
    }
    return blocks;
  }

  // Stage k's excavation and installation against the blocks present at its start (`count` of
  // them).
  void check_changes(std::size_t k, const std::vector<int>& excavated,
                     const std::vector<int>& installed, std::size_t count) const {
    std::vector<int> both;
    std::set_intersection(excavated.begin(), excavated.end(), installed.begin(), installed.end(),
                          std::back_inserter(both));
    if (!both.empty())
      fail(where(k, "install"), describe(both.front()) + " is also excavated by this stage");
    for (const int b : excavated) {
      if (!present_[b])
        fail(where(k, "excavate"), describe(b) + " is absent at this stage: " + absence(b));
    }
    if (!excavated.empty() && excavated.size() == count)
      fail(where(k, "excavate"),
           "excavates every block present at this stage: at least one must remain");
  }

  void check_release(std::size_t k, bool any_excavated) const {
    const StageSpec& st = stages_[k];
    const SourceRef ref{st.source.line, st.source.item + ".release"};
    if (!std::isfinite(st.release) || st.release <= 0.0 || st.release > 1.0)
      fail(ref, "must lie in (0, 1]: the fraction of the unreleased excavation forces released");
    if (st.release != 1.0 && !any_excavated)
      fail(ref,
           "no stage up to this one excavates a block: release applies to the forces of excavated "
           "blocks not yet released");
  }

  // A stage's point loads, tractions and controlled monitor act on blocks present during it.
  void check_loads(std::size_t k, std::size_t count) const {
    if (count == present_.size())
      return;  // every block present: the loads' blocks exist
    const StageSpec& spec = stages_[k];
    const Stage& st = model_.stages[k];
    for (std::size_t p = 0; p < st.loads.points.size(); ++p) {
      const int b = st.loads.points[p].block;
      if (!present_[b])
        fail(spec.loads.points[p].source,
             "acts on " + describe(b) + ", which is absent during this stage: " + absence(b));
    }
    for (const TractionSpec& t : spec.loads.tractions) {
      for (const BoundaryEdge& e : model_.boundary) {
        if (!present_[e.polygon] && selects(t.where, e.segment, model_.tolerance))
          fail(t.source, "acts on an edge of " + describe(e.polygon) +
                             ", which is absent during this stage: " + absence(e.polygon));
      }
    }
    if (st.control) {
      const Monitor& m = model_.monitors[static_cast<std::size_t>(st.control->monitor)];
      if (!present_[m.block])
        fail(spec.control->source, "monitor '" + m.name + "' follows " + describe(m.block) +
                                       ", which is absent during this stage: " + absence(m.block));
    }
  }

  Model& model_;
  const std::vector<StageSpec>& stages_;
  std::vector<int> installed_by_;  // per block: the stage that installs it, or kNever
  std::vector<int> excavated_by_;  // per block: the stage that excavated it, or kNever
  std::vector<char> present_;      // per block, during the stage being resolved
};

}  // namespace

void resolve_stage_blocks(Model& model, const std::vector<StageSpec>& stages) {
  if (model.stages.size() != stages.size())
    throw std::invalid_argument("resolve_stage_blocks: the model's stages are not those given");
  StageBlocks(model, stages).resolve();
}

bool present_at_start(const Model& model, int block) {
  return std::none_of(model.stages.begin(), model.stages.end(), [&](const Stage& stage) {
    return std::binary_search(stage.installed.begin(), stage.installed.end(), block);
  });
}

std::vector<char> blocks_present(const Model& model, int stage) {
  if (stage < -1 || stage >= static_cast<int>(model.stages.size()))
    throw std::out_of_range("blocks_present: no stage " + std::to_string(stage));
  std::vector<char> present(model.blocks.size(), 1);
  for (const Stage& st : model.stages) {
    for (const int b : st.installed)
      present[static_cast<std::size_t>(b)] = 0;
  }
  for (int k = 0; k <= stage; ++k) {
    for (const int b : model.stages[static_cast<std::size_t>(k)].excavated)
      present[static_cast<std::size_t>(b)] = 0;
    for (const int b : model.stages[static_cast<std::size_t>(k)].installed)
      present[static_cast<std::size_t>(b)] = 1;
  }
  return present;
}

}  // namespace bimrock
