#include <bimrock/solve/column_equations.hpp>

#include <cmath>
#include <utility>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include <bimrock/solve/kernel_certificate.hpp>

namespace bimrock {

ActiveSetEquations::Solution ColumnEquations::solve(const std::vector<Eigen::Index>& rows,
                                                    const Damping& damping, Check /*check*/) {
  const Eigen::Index n = size();
  fetch(rows);
  const auto k = static_cast<Eigen::Index>(rows.size());
  Eigen::MatrixXd m_rows(n, k);  // the columns of M of the active rows
  for (Eigen::Index c = 0; c < k; ++c)
    m_rows.col(c) = known_.col(slot_[static_cast<std::size_t>(rows[static_cast<std::size_t>(c)])]);
  Eigen::MatrixXd a(k, k);
  Eigen::VectorXd rhs(k);
  for (Eigen::Index r = 0; r < k; ++r) {
    const Eigen::Index i = rows[static_cast<std::size_t>(r)];
    a.row(r) = m_rows.row(i);
    rhs(r) = -q()(i);
    if (damping.factor.size() > 0) {
      const double d = damping.factor(r) * a(r, r);
      a(r, r) += d;
      rhs(r) += d * damping.center(i);
    }
  }
  Solution out;
  out.z = Eigen::VectorXd::Zero(n);
  Eigen::VectorXd za = Eigen::VectorXd::Zero(k);
  if (k > 0) {
    // One step of iterative refinement after the solve.
    const auto refined = [&](const auto& factor) {
      Eigen::VectorXd x = factor.solve(rhs);
      x += factor.solve(rhs - a * x);
      return x;
    };
    // A symmetric block is positive semi-definite (the LCP is a convex program): Cholesky,
    // half the work of LU, unless it is singular.
    const Eigen::LLT<Eigen::MatrixXd> llt =
        problem_.symmetric() ? Eigen::LLT<Eigen::MatrixXd>(a) : Eigen::LLT<Eigen::MatrixXd>();
    if (problem_.symmetric() && llt.info() == Eigen::Success && llt.rcond() > singular_tolerance_) {
      za = refined(llt);
    } else {
      const Eigen::PartialPivLU<Eigen::MatrixXd> lu(a);
      if (!(lu.rcond() > singular_tolerance_)) {
        if (problem_.symmetric())
          out.ray = kernel_certificate(a, m_rows, q(), rows);
        return out;
      }
      za = refined(lu);
    }
    for (Eigen::Index r = 0; r < k; ++r)
      out.z(rows[static_cast<std::size_t>(r)]) = za(r);
  }
  out.w = m_rows * za + q();
  out.w_scale = m_rows.cwiseAbs() * za.cwiseAbs() + q().cwiseAbs();
  out.regular = true;
  return out;
}

// Any z: the columns of its support are asked for if not known yet.
LcpResult ColumnEquations::result(LcpStatus status, Eigen::VectorXd z, int steps) {
  std::vector<Eigen::Index> support;
  for (Eigen::Index i = 0; i < z.size(); ++i)
    if (z(i) != 0.0)
      support.push_back(i);
  fetch(support);
  LcpResult r;
  r.status = status;
  r.w = q();
  Eigen::VectorXd sizes = q().cwiseAbs();
  for (Eigen::Index i : support) {
    const auto column = known_.col(slot_[static_cast<std::size_t>(i)]);
    r.w += z(i) * column;
    sizes += std::abs(z(i)) * column.cwiseAbs();
  }
  r.residuals = measure(z, r.w, sizes);
  r.z = std::move(z);
  r.steps = steps;
  return r;
}

// Asks for the columns of `rows` not known yet: column slot_[i] of known_ is column i of M.
void ColumnEquations::fetch(const std::vector<Eigen::Index>& rows) {
  std::vector<Eigen::Index> missing;
  for (Eigen::Index i : rows)
    if (slot_[static_cast<std::size_t>(i)] < 0)
      missing.push_back(i);
  if (missing.empty())
    return;
  const Eigen::MatrixXd fresh = problem_.columns(missing);
  const Eigen::Index first = known_.cols();
  known_.conservativeResize(size(), first + fresh.cols());
  known_.rightCols(fresh.cols()) = fresh;
  for (std::size_t k = 0; k < missing.size(); ++k)
    slot_[static_cast<std::size_t>(missing[k])] = first + static_cast<Eigen::Index>(k);
}

}  // namespace bimrock
