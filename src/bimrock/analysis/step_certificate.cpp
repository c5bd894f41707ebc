#include <bimrock/analysis/step_certificate.hpp>

#include <bimrock/solve/lcp.hpp>

namespace bimrock {

std::optional<double> certified_step_fraction(const StageContext& ctx, const YieldSystem& sys,
                                              const IncrementLcp& lcp, const Eigen::VectorXd& r) {
  // M^T r = N^T r - Phi^T K^-1 C^T r, and the size of the terms each entry sums.
  const Eigen::VectorXd x = ctx.k.solve(Eigen::VectorXd(sys.c.transpose() * r));
  const Eigen::VectorXd mtr = sys.n.transpose() * r - sys.phi.transpose() * x;
  const Eigen::VectorXd sizes = SparseMatrix(sys.n.cwiseAbs().transpose()) * r +
                                SparseMatrix(sys.phi.cwiseAbs().transpose()) * x.cwiseAbs();
  // q as the LCP holds it, shifted by M gap_old: an opening row's unknown is the total gap.
  Eigen::VectorXd q = lcp.q;
  if (lcp.gap_old.size() == q.size() && lcp.gap_old.cwiseAbs().maxCoeff() > 0.0)
    q -= sys.n * lcp.gap_old - sys.c * ctx.k.solve(Eigen::VectorXd(sys.phi * lcp.gap_old));
  const double m_max = sys.n.diagonal().cwiseAbs().maxCoeff();  // M_ii <= N_ii
  if (!certifies_infeasibility(q, r, mtr, sizes, m_max))
    return std::nullopt;
  return lcp.load_part.size() == q.size() ? certified_from(q, lcp.load_part, r) : 1.0;
}

}  // namespace bimrock
