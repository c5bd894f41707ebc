#pragma once
// A second method for collapse loads: the static theorem of limit analysis for rigid blocks,
// as a linear program of its own (GLPK), independent of the increments' LCPs.
//
// Every interface carries a normal force N (compression positive) and a shear force V at each
// of its two end points, where bimrock's Lobatto springs sit, each with half the interface's
// length. The yield conditions are those of the joint material's peak strength on that half:
// N >= -sigma_t w and |V| <= c w + N tan(phi), w = length / 2 x thickness. The blocks' own
// stress is unlimited (blocks without strength), so the three equations of each block's
// strain are met by its stress, and a statically admissible state is one in which the point
// forces balance each block's loads as a rigid body. The largest factor of the live loads for
// which one exists is the associated collapse load of the elastic-plastic block model
// (docs/formulation.md), and by the static theorem no flow rule carries more.
#include <limits>
#include <optional>
#include <stdexcept>
#include <vector>

#include <glpk.h>

#include <bimrock/model/model.hpp>

namespace bimrock::testing {

/// The loads one block feels from `loads` as a rigid body: the force and its moment about the
/// origin. Gravity and point loads only.
inline void add_rigid_loads(const Model& model, const Loads& loads,
                            std::vector<Eigen::Vector3d>& per_block) {
  if (!loads.tractions.empty() || !loads.water.empty())
    throw std::invalid_argument("rigid_block_limit: gravity and point loads only");
  const auto add = [&](int block, const Vec2& at, const Vec2& f) {
    per_block[static_cast<std::size_t>(block)] +=
        Eigen::Vector3d(f.x(), f.y(), at.x() * f.y() - at.y() * f.x());
  };
  for (std::size_t b = 0; b < model.blocks.size(); ++b) {
    const Block& block = model.blocks[b];
    const double weight =
        model.block_materials[static_cast<std::size_t>(block.material)].unit_weight * block.area *
        model.settings.thickness;
    add(static_cast<int>(b), block.centroid, weight * loads.gravity);
  }
  for (const PointLoad& p : loads.points)
    add(p.block, p.point, p.force);
}

/// The largest factor of `live` that rigid blocks carry together with `dead`: infinity where
/// the program is unbounded, none where not even `dead` alone is carried. `reduction` divides
/// every joint's strength (tan(phi), c and sigma_t), as strength reduction does.
inline std::optional<double> rigid_block_limit_factor(const Model& model, const Loads& dead,
                                                      const Loads& live, double reduction = 1.0) {
  const int n_blocks = static_cast<int>(model.blocks.size());
  std::vector<Eigen::Vector3d> fixed(static_cast<std::size_t>(n_blocks), Eigen::Vector3d::Zero());
  std::vector<Eigen::Vector3d> scaled(static_cast<std::size_t>(n_blocks), Eigen::Vector3d::Zero());
  add_rigid_loads(model, dead, fixed);
  add_rigid_loads(model, live, scaled);

  glp_prob* lp = glp_create_prob();
  glp_set_obj_dir(lp, GLP_MAX);
  // Rows 1 .. 3 n_blocks: each block's balance, sum of forces = -(dead loads) with the live
  // loads' column; then two slip rows per point.
  glp_add_rows(lp, 3 * n_blocks);
  for (int b = 0; b < n_blocks; ++b)
    for (int k = 0; k < 3; ++k) {
      const double rhs = -fixed[static_cast<std::size_t>(b)](k);
      glp_set_row_bnds(lp, 3 * b + k + 1, GLP_FX, rhs, rhs);
    }
  std::vector<int> ia{0};
  std::vector<int> ja{0};
  std::vector<double> ar{0.0};
  const auto entry = [&](int row, int col, double value) {
    if (value != 0.0) {
      ia.push_back(row);
      ja.push_back(col);
      ar.push_back(value);
    }
  };
  // Column 1: the live loads' factor.
  glp_add_cols(lp, 1);
  glp_set_col_bnds(lp, 1, GLP_LO, 0.0, 0.0);
  glp_set_obj_coef(lp, 1, 1.0);
  for (int b = 0; b < n_blocks; ++b)
    for (int k = 0; k < 3; ++k)
      entry(3 * b + k + 1, 1, scaled[static_cast<std::size_t>(b)](k));
  // A force F at point P on a block adds (F, P x F) to its balance.
  const auto force_on = [&](int block, const Vec2& at, const Vec2& direction, int col,
                            double sign) {
    const Vec2 d = sign * direction;
    entry(3 * block + 1, col, d.x());
    entry(3 * block + 2, col, d.y());
    entry(3 * block + 3, col, at.x() * d.y() - at.y() * d.x());
  };
  for (const Interface& f : model.interfaces) {
    if (f.joint_material < 0)
      throw std::invalid_argument("rigid_block_limit: every interface needs a joint material");
    const JointMaterial& m = model.joint_materials[static_cast<std::size_t>(f.joint_material)];
    if (!m.strength)
      throw std::invalid_argument("rigid_block_limit: every joint material needs a strength");
    const double tan_phi = m.strength->friction.peak / reduction;
    const double c = m.strength->cohesion.peak / reduction;
    const double sigma_t = m.strength->tensile.peak / reduction;
    const double w = 0.5 * f.segment.length() * model.settings.thickness;
    const Vec2 s(-f.normal.y(), f.normal.x());
    for (const Vec2& at : {f.segment.a, f.segment.b}) {
      // N and V: block i pushes block j along the normal (from i into j).
      const int n_col = glp_add_cols(lp, 2);
      const int v_col = n_col + 1;
      glp_set_col_bnds(lp, n_col, GLP_LO, -sigma_t * w, 0.0);
      glp_set_col_bnds(lp, v_col, GLP_FR, 0.0, 0.0);
      force_on(f.block_i, at, f.normal, n_col, -1.0);
      force_on(f.block_i, at, s, v_col, -1.0);
      if (!f.is_support()) {
        force_on(f.block_j, at, f.normal, n_col, 1.0);
        force_on(f.block_j, at, s, v_col, 1.0);
      }
      // +V - tan(phi) N <= c w and -V - tan(phi) N <= c w.
      const int row = glp_add_rows(lp, 2);
      for (int k = 0; k < 2; ++k) {
        glp_set_row_bnds(lp, row + k, GLP_UP, 0.0, c * w);
        entry(row + k, v_col, k == 0 ? 1.0 : -1.0);
        entry(row + k, n_col, -tan_phi);
      }
    }
  }
  glp_load_matrix(lp, static_cast<int>(ia.size()) - 1, ia.data(), ja.data(), ar.data());
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;  // then the status says infeasible or unbounded
  // The simplex in floating point, then in exact rational arithmetic from its basis: on the
  // short interfaces where columns of unequal height meet, the floating simplex alone can stop
  // 1.5% short of the optimum and call it optimal.
  glp_simplex(lp, &parm);
  const int code = glp_exact(lp, &parm);
  std::optional<double> factor;
  if (code == 0 && glp_get_status(lp) == GLP_OPT)
    factor = glp_get_obj_val(lp);
  else if (code == 0 && glp_get_status(lp) == GLP_UNBND)
    factor = std::numeric_limits<double>::infinity();
  glp_delete_prob(lp);
  return factor;
}

/// The factor of safety of rigid blocks under the loads of the model's first stage: the largest
/// divisor of the joints' strengths with which they are carried, to a relative 1e-9, or
/// `largest` where that is carried.
inline double rigid_block_factor_of_safety(const Model& model, double largest) {
  const auto carried = [&](double reduction) {
    const std::optional<double> f =
        rigid_block_limit_factor(model, Loads{}, model.stages[0].loads, reduction);
    return f && *f >= 1.0;
  };
  if (carried(largest))
    return largest;
  double lower = 0.0;  // strengths without bound carry anything a support can
  double upper = largest;
  while (upper - lower > 1e-9 * upper) {
    const double mid = 0.5 * (lower + upper);
    (carried(mid) ? lower : upper) = mid;
  }
  return 0.5 * (lower + upper);
}

}  // namespace bimrock::testing
