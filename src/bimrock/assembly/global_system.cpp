#include <bimrock/assembly/global_system.hpp>

#include <algorithm>
#include <array>
#include <vector>

#include <bimrock/assembly/integration_points.hpp>
#include <bimrock/assembly/kinematics.hpp>
#include <bimrock/assembly/local_stiffness.hpp>
#include <bimrock/assembly/stiffness_terms.hpp>

namespace bimrock {
namespace {

// The lower triangle of K in compressed columns, its pattern built from the block graph first
// (each block couples with itself, with its neighbours across interfaces and with the blocks its
// bolts' springs join, whether they stand yet or not: one pattern for every stage), so values
// are added in place: no triplet list five times the size of K.
class LowerAssembler final : public StiffnessSink {
 public:
  LowerAssembler(const Model& model, SparseMatrix& k) : neighbours_(model.n_blocks()), k_(k) {
    for (const Interface& f : model.interfaces) {
      if (f.is_support())
        continue;
      const int lo = std::min(f.block_i, f.block_j);
      const int hi = std::max(f.block_i, f.block_j);
      neighbours_[lo].push_back(hi);
    }
    for (const BoltSpring& s : model.bolt_springs)
      neighbours_[std::min(s.block_a, s.block_b)].push_back(std::max(s.block_a, s.block_b));
    const std::int64_t n = model.n_dofs();
    std::int64_t nnz = 0;
    for (int b = 0; b < model.n_blocks(); ++b) {
      auto& nb = neighbours_[b];
      std::sort(nb.begin(), nb.end());
      nb.erase(std::unique(nb.begin(), nb.end()), nb.end());
      nnz += 21 + 36 * static_cast<std::int64_t>(nb.size());
    }
    // Write the compressed-column arrays directly: rows sorted within each column.
    k_.resize(n, n);
    k_.resizeNonZeros(nnz);
    std::int64_t* outer = k_.outerIndexPtr();
    std::int64_t* inner = k_.innerIndexPtr();
    std::int64_t next = 0;
    for (int b = 0; b < model.n_blocks(); ++b) {
      for (int a = 0; a < 6; ++a) {
        const std::int64_t c = 6 * b + a;
        outer[c] = next;
        for (std::int64_t r = c; r < 6 * b + 6; ++r)
          inner[next++] = r;
        for (int j : neighbours_[b])
          for (int d = 0; d < 6; ++d)
            inner[next++] = 6 * j + d;
      }
    }
    outer[n] = next;
    std::fill(k_.valuePtr(), k_.valuePtr() + nnz, 0.0);
  }

  [[nodiscard]] bool wants(int) const override { return true; }
  void add(const Mat6& local, int block) override { add_lower<6>(local, {block}); }
  void add(const Mat12& local, int block_i, int block_j) override {
    add_lower<12>(local, {block_i, block_j});
  }

 private:
  // Adds the lower triangle of the local matrix whose local block r belongs to block ids[r].
  template <int N>
  void add_lower(const Eigen::Matrix<double, N, N>& local, const std::array<int, N / 6>& ids) {
    for (int c = 0; c < N; ++c) {
      const std::int64_t gc = 6 * ids[c / 6] + c % 6;
      for (int r = 0; r < N; ++r) {
        const std::int64_t gr = 6 * ids[r / 6] + r % 6;
        if (gr >= gc)
          k_.valuePtr()[position(gr, gc)] += local(r, c);
      }
    }
  }

  // Index of entry (row, col), row >= col, in the value array.
  std::int64_t position(std::int64_t row, std::int64_t col) const {
    const std::int64_t b = col / 6;
    const std::int64_t a = col % 6;
    std::int64_t offset = row - col;  // inside the diagonal block
    if (row >= 6 * b + 6) {
      const auto& nb = neighbours_[b];
      const auto it = std::lower_bound(nb.begin(), nb.end(), static_cast<int>(row / 6));
      offset = (6 - a) + 6 * (it - nb.begin()) + row % 6;
    }
    return k_.outerIndexPtr()[col] + offset;
  }

  std::vector<std::vector<int>> neighbours_;  // per block, the neighbours of higher index
  SparseMatrix& k_;  // assembled in place: Eigen 3.4's SparseMatrix has no move constructor
};

}  // namespace

SparseMatrix assemble_stiffness_lower(const Model& model) {
  return assemble_stiffness_lower(model, every_block(model));
}

SparseMatrix assemble_stiffness_lower(const Model& model, const Presence& present) {
  SparseMatrix lower;
  LowerAssembler k(model, lower);
  add_stiffness_terms(model, present, k);
  return lower;
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
    p.segment<6>(6 * l.block) +=
        block_Q(model.blocks[l.block].centroid, l.point).transpose() * l.force;
  }
  for (const Traction& tr : loads.tractions) {
    const Vec2 traction = tr.normal * tr.outward_normal + tr.shear * perp(tr.outward_normal);
    for (const IntegrationPoint& ip : integration_points(tr.segment, Integration::gauss)) {
      p.segment<6>(6 * tr.block) += (t * ip.weight) *
                                    block_Q(model.blocks[tr.block].centroid, ip.point).transpose() *
                                    traction;
    }
  }
  // Water pushes into each wet face: traction -p n, p linear along the piece (2-point Gauss is
  // exact for it times the linear Q).
  for (const PressureFace& w : loads.water) {
    const double length = w.segment.length();
    for (const IntegrationPoint& ip : integration_points(w.segment, Integration::gauss)) {
      const double s = (ip.point - w.segment.a).norm() / length;
      const double pressure = w.pressure_a + s * (w.pressure_b - w.pressure_a);
      p.segment<6>(6 * w.block) -= (t * ip.weight * pressure) *
                                   block_Q(model.blocks[w.block].centroid, ip.point).transpose() *
                                   w.outward_normal;
    }
  }
  return p;
}

}  // namespace bimrock
