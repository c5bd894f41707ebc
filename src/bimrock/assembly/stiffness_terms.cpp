#include <bimrock/assembly/stiffness_terms.hpp>

namespace bimrock {

void add_stiffness_terms(const Model& model, const Presence& present, StiffnessSink& sink) {
  const double t = model.settings.thickness;
  for (int b = 0; b < model.n_blocks(); ++b) {
    if (!sink.wants(b))
      continue;
    const Block& block = model.blocks[b];
    const BlockMaterial& material = model.block_materials[block.material];
    if (!present.block(b)) {
      // Any positive diagonal decouples the unknowns; t E keeps it of K's order.
      sink.add(Mat6(Mat6::Identity() * t * material.young), b);
      continue;
    }
    sink.add(block_stiffness(block, elasticity_matrix(material, model.settings.plane), t), b);
  }
  for (const Interface& f : model.interfaces) {
    const bool support = f.is_support();
    if (!present.block(f.block_i) || (!support && !present.block(f.block_j)))
      continue;
    if (!sink.wants(f.block_i) && (support || !sink.wants(f.block_j)))
      continue;
    const Vec2& ci = model.blocks[f.block_i].centroid;
    if (support)
      sink.add(support_stiffness(f, ci, t), f.block_i);
    else
      sink.add(interface_stiffness(f, ci, model.blocks[f.block_j].centroid, t), f.block_i,
               f.block_j);
  }
  for (std::size_t s = 0; s < model.bolt_springs.size(); ++s) {
    const BoltSpring& spring = model.bolt_springs[s];
    if (present.spring(static_cast<int>(s)) &&
        (sink.wants(spring.block_a) || sink.wants(spring.block_b)))
      sink.add(bolt_stiffness(model, spring), spring.block_a, spring.block_b);
  }
}

}  // namespace bimrock
