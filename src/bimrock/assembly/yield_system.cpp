#include <bimrock/assembly/yield_system.hpp>

namespace bimrock {

YieldSystem assemble_yield_system(const Model& model, const std::vector<YieldPoint>& points,
                                  const std::vector<PlasticState>& states, const Eigen::VectorXd& u,
                                  const std::vector<int>& candidates, FlowRule flow,
                                  double toward_gradient) {
  YieldSystem sys;
  std::vector<Eigen::Triplet<double, std::int64_t>> phi;
  std::vector<Eigen::Triplet<double, std::int64_t>> c;
  std::vector<Eigen::Triplet<double, std::int64_t>> n;
  std::vector<double> f0;
  for (int p : candidates) {
    const YieldPoint& point = points[p];
    const LocalOperator op = local_operator(model, point);
    const Eigen::MatrixXd d = local_stiffness(model, point);
    const Eigen::VectorXd stress = local_stress(model, point, states[p], u);
    LocalYield y = linearize(model, point, states[p], stress);
    if (toward_gradient != 0.0)
      y.g += toward_gradient * (y.a - y.g);
    if (flow == FlowRule::associated)
      y.g = y.a;
    else if (flow == FlowRule::gradient_along_flow)
      y.a = y.g;
    const double w = point.weight;
    const Eigen::MatrixXd a_d_e = w * y.a * d * op.e;  // scaled C rows, local columns
    const Eigen::MatrixXd e_d_g = w * op.e.transpose() * d * y.g.transpose();  // Phi columns
    const int first = sys.size();
    for (int mode = 0; mode < y.a.rows(); ++mode) {
      const int row = first + mode;
      sys.rows.push_back({p, mode});
      Eigen::Vector3d g = Eigen::Vector3d::Zero();
      g.head(y.g.cols()) = y.g.row(mode).transpose();
      sys.flow.push_back(g);
      f0.push_back(w * y.f(mode));
      for (int k = 0; k < op.n_blocks(); ++k) {
        for (int dof = 0; dof < 6; ++dof) {
          const std::int64_t global = 6 * op.blocks[k] + dof;
          if (a_d_e(mode, 6 * k + dof) != 0.0)
            c.emplace_back(row, global, a_d_e(mode, 6 * k + dof));
          if (e_d_g(6 * k + dof, mode) != 0.0)
            phi.emplace_back(global, row, e_d_g(6 * k + dof, mode));
        }
      }
    }
    const Eigen::MatrixXd n_point = w * (y.a * d * y.g.transpose() + y.h);
    for (Eigen::Index j = 0; j < n_point.cols(); ++j)
      for (Eigen::Index i = 0; i < n_point.rows(); ++i)
        if (n_point(i, j) != 0.0)
          n.emplace_back(first + i, first + j, n_point(i, j));
  }
  const int m = sys.size();
  sys.phi.resize(model.n_dofs(), m);
  sys.phi.setFromTriplets(phi.begin(), phi.end());
  sys.c.resize(m, model.n_dofs());
  sys.c.setFromTriplets(c.begin(), c.end());
  sys.n.resize(m, m);
  sys.n.setFromTriplets(n.begin(), n.end());
  sys.f0 = Eigen::Map<const Eigen::VectorXd>(f0.data(), m);
  return sys;
}

bool follows_associated_flow(const YieldSystem& sys) {
  const SparseMatrix asymmetry = sys.c - SparseMatrix(sys.phi.transpose());
  const SparseMatrix n_asymmetry = sys.n - SparseMatrix(sys.n.transpose());
  return asymmetry.norm() <= 1e-12 * sys.c.norm() && n_asymmetry.norm() <= 1e-12 * sys.n.norm();
}

}  // namespace bimrock
