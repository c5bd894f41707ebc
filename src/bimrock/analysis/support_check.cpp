#include <bimrock/analysis/support_check.hpp>

#include <numeric>

#include <Eigen/Eigenvalues>

#include <bimrock/assembly/local_stiffness.hpp>

namespace bimrock {
namespace {

struct UnionFind {
  std::vector<int> parent;
  explicit UnionFind(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  int find(int x) {
    while (parent[x] != x)
      x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(int a, int b) { parent[find(a)] = find(b); }
};

// Block unknowns produced by a rigid motion (U, V, omega) of a group about point o.
Eigen::Matrix<double, 6, 3> rigid_modes(const Vec2& c, const Vec2& o) {
  Eigen::Matrix<double, 6, 3> r = Eigen::Matrix<double, 6, 3>::Zero();
  r(0, 0) = 1.0;
  r(1, 1) = 1.0;
  r(0, 2) = -(c.y() - o.y());
  r(1, 2) = c.x() - o.x();
  r(2, 2) = 1.0;
  return r;
}

}  // namespace

std::string name_blocks(const Model& model, const std::vector<int>& blocks) {
  std::string s;
  const std::size_t shown = std::min<std::size_t>(blocks.size(), 5);
  for (std::size_t k = 0; k < shown; ++k) {
    const Block& b = model.blocks[blocks[k]];
    if (k > 0)
      s += (k + 1 == shown && shown == blocks.size()) ? " and " : ", ";
    s += b.source.item.empty() ? "block " + std::to_string(blocks[k]) : b.source.item;
    if (b.source.line > 0)
      s += " (line " + std::to_string(b.source.line) + ")";
  }
  if (blocks.size() > shown)
    s += " and " + std::to_string(blocks.size() - shown) + " more";
  return s;
}

void check_supports(const Model& model) {
  const int n = model.n_blocks();
  UnionFind groups(n);
  for (const Interface& f : model.interfaces) {
    if (!f.is_support() && f.normal_stiffness > 0.0)
      groups.unite(f.block_i, f.block_j);
  }
  // Support stiffness seen by the rigid motions of each group, about the group's first block.
  std::vector<Eigen::Matrix3d> held(n, Eigen::Matrix3d::Zero());
  std::vector<double> scale(n, 0.0);
  const double t = model.settings.thickness;
  for (const Interface& f : model.interfaces) {
    if (!f.is_support())
      continue;
    const int g = groups.find(f.block_i);
    const Vec2& c = model.blocks[f.block_i].centroid;
    const Eigen::Matrix<double, 6, 3> r = rigid_modes(c, model.blocks[g].centroid);
    // Which rigid motions a support resists depends on its geometry and on which of its springs
    // are non-zero, not on how stiff they are. Summing the supports' own stiffnesses let a rigid
    // penalty roller (kn ~ 1e17 Pa/m) swamp a soft layer's shear (ks ~ 1e8 Pa/m) below the
    // eigenvalue tolerance, and a held structure was refused. So each spring enters with unit
    // stiffness: the tolerance then measures geometric degeneracy only.
    for (const bool normal : {true, false}) {
      if ((normal ? f.normal_stiffness : f.shear_stiffness) <= 0.0)
        continue;
      Interface unit = f;
      unit.normal_stiffness = normal ? 1.0 : 0.0;
      unit.shear_stiffness = normal ? 0.0 : 1.0;
      held[g] += r.transpose() * support_stiffness(unit, c, t) * r;
    }
    scale[g] = std::max(scale[g], f.normal_stiffness * f.segment.length() * t);
  }
  std::vector<std::vector<int>> members(n);
  for (int k = 0; k < n; ++k)
    members[groups.find(k)].push_back(k);
  for (int g = 0; g < n; ++g) {
    if (members[g].empty())
      continue;
    bool free = scale[g] == 0.0;
    if (!free) {
      // Make the rotation column commensurate with translations by the group's size.
      double size = 0.0;
      for (int k : members[g]) {
        size = std::max(size, (model.blocks[k].centroid - model.blocks[g].centroid).norm() +
                                  std::sqrt(model.blocks[k].area));
      }
      const Eigen::Vector3d s(1.0, 1.0, 1.0 / size);
      const Eigen::Matrix3d h = s.asDiagonal() * held[g] * s.asDiagonal();
      const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(h);
      free = eig.eigenvalues()(0) <= 1e-9 * eig.eigenvalues()(2);
    }
    if (free) {
      throw ModelError("the structure is not fully supported: " + name_blocks(model, members[g]) +
                           (scale[g] == 0.0 ? " have no support and can move freely"
                                            : " can move as a rigid body (the supports leave a "
                                              "translation or rotation free)"),
                       members[g]);
    }
  }
}

void report_singular_stiffness(const Model& model, long row) {
  const int block = static_cast<int>(row / 6);
  throw ModelError("the structure is not fully supported: the stiffness is singular at " +
                       name_blocks(model, {block}) +
                       ", which can move freely (check joints without shear stiffness and rollers)",
                   {block});
}

}  // namespace bimrock
