#include <bimrock/solve/solve_accuracy.hpp>

#include <cmath>

namespace bimrock {

double solve_accuracy(const SpdSolver& k, const SparseMatrix& k_lower) {
  // A known solution with every entry of its own size and sign pattern, so that it has parts
  // along the soft and the stiff modes of K alike.
  Eigen::VectorXd known(k_lower.rows());
  for (Eigen::Index i = 0; i < known.size(); ++i)
    known(i) = std::sin(1.0 + 0.7 * static_cast<double>(i));
  const Eigen::VectorXd b = k_lower.selfadjointView<Eigen::Lower>() * known;
  const double size = known.norm();
  return size > 0.0 ? (k.solve(b) - known).norm() / size : 0.0;
}

}  // namespace bimrock
