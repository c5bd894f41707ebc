#include <bimrock/assembly/global_system.hpp>

#include <vector>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/local_stiffness.hpp>

namespace bimrock {
namespace {

using Triplets = std::vector<Eigen::Triplet<double, std::int64_t>>;

// Adds the lower triangle of the local matrix `k` whose local block r belongs to block ids[r].
template <int N>
void scatter_lower(const Eigen::Matrix<double, N, N>& k, const std::array<int, N / 6>& ids,
                   Triplets& out) {
  for (int c = 0; c < N; ++c) {
    const int gc = 6 * ids[c / 6] + c % 6;
    for (int r = 0; r < N; ++r) {
      const int gr = 6 * ids[r / 6] + r % 6;
      if (gr >= gc && k(r, c) != 0.0) out.emplace_back(gr, gc, k(r, c));
    }
  }
}

}  // namespace

SparseMatrix assemble_stiffness_lower(const Model& model) {
  Triplets triplets;
  triplets.reserve(21 * model.blocks.size() + 78 * model.interfaces.size() * 2);
  const double t = model.settings.thickness;
  for (int k = 0; k < model.n_blocks(); ++k) {
    const Block& b = model.blocks[k];
    const Eigen::Matrix3d d_b =
        elasticity_matrix(model.block_materials[b.material], model.settings.plane);
    scatter_lower<6>(block_stiffness(b, d_b, t), {k}, triplets);
  }
  for (const Interface& f : model.interfaces) {
    const Vec2& ci = model.blocks[f.block_i].centroid;
    if (f.is_support()) {
      scatter_lower<6>(support_stiffness(f, ci, t), {f.block_i}, triplets);
    } else {
      const Vec2& cj = model.blocks[f.block_j].centroid;
      scatter_lower<12>(interface_stiffness(f, ci, cj, t), {f.block_i, f.block_j}, triplets);
    }
  }
  SparseMatrix k(model.n_dofs(), model.n_dofs());
  k.setFromTriplets(triplets.begin(), triplets.end());
  k.makeCompressed();
  return k;
}

SparseMatrix full_from_lower(const SparseMatrix& lower) {
  SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
  full.makeCompressed();
  return full;
}

Eigen::VectorXd assemble_loads(const Model& model, const Loads& loads) {
  Eigen::VectorXd p = Eigen::VectorXd::Zero(model.n_dofs());
  const double t = model.settings.thickness;
  if (loads.gravity.squaredNorm() > 0.0) {
    for (int k = 0; k < model.n_blocks(); ++k) {
      const Block& b = model.blocks[k];
      const double w = t * b.area * model.block_materials[b.material].unit_weight;
      p.segment<2>(6 * k) += w * loads.gravity;
    }
  }
  for (const PointLoad& l : loads.points) {
    p.segment<6>(6 * l.block) += block_Q(model.blocks[l.block].centroid, l.point).transpose() * l.force;
  }
  for (const Traction& tr : loads.tractions) {
    const Vec2 traction = tr.normal * tr.outward_normal + tr.shear * perp(tr.outward_normal);
    for (const IntegrationPoint& ip : integration_points(tr.segment, Integration::gauss)) {
      p.segment<6>(6 * tr.block) +=
          (t * ip.weight) * block_Q(model.blocks[tr.block].centroid, ip.point).transpose() * traction;
    }
  }
  return p;
}

}  // namespace bimrock
