#include <bimrock/solve/unsymmetric_tangent.hpp>

#include <cmath>

#include <Eigen/UmfPackSupport>

namespace bimrock {

// UMFPACK's solves read the matrix again (iterative refinement), and Eigen's wrapper keeps
// only a view of it: the tangent lives beside its factor.
struct UnsymmetricTangentEquations::Lu {
  CholmodMatrix tangent;
  Eigen::UmfPackLU<CholmodMatrix> lu;
};

UnsymmetricTangentEquations::UnsymmetricTangentEquations(const SplitLcp& lcp, const SpdSolver& s)
    : SplitLcpEquations(lcp, s),
      s_full_(lcp.k_lower->selfadjointView<Eigen::Lower>()),
      lu_(std::make_unique<Lu>()) {}

UnsymmetricTangentEquations::~UnsymmetricTangentEquations() = default;

ActiveSetEquations::Solution UnsymmetricTangentEquations::solve(
    const std::vector<Eigen::Index>& active, const Damping& damping, Check check) {
  const Eigen::Index n = s_full_.rows();
  Solution out = start(active);
  if (active.empty())
    return out;
  const std::optional<std::vector<Local>> found = locals(active, damping);
  if (!found)
    return out;
  const std::vector<Local>& locals = *found;
  // The tangent S - Phi_A N_AA^-1 C_A, its plastic part as triplets: each term couples only the
  // unknowns of the blocks its yield point joins, so the tangent keeps S's pattern.
  std::vector<Eigen::Triplet<double, std::int64_t>> plastic;
  for (const Local& l : locals)
    add_plastic_coupling(*lcp_.phi, c_transposed_, &active[l.first], l.inverse, plastic);
  CholmodMatrix part(n, n);
  part.setFromTriplets(plastic.begin(), plastic.end());
  lu_->tangent = s_full_ - part;
  lu_->lu.compute(lu_->tangent);
  ++factorizations_;
  if (lu_->lu.info() != Eigen::Success)
    return out;  // singular: the dense route decides
  const double worst = solve_through(
      active, locals, damping, check,
      [&](const Eigen::VectorXd& rhs) { return Eigen::VectorXd(lu_->lu.solve(rhs)); }, out);
  out.regular = std::isfinite(worst);
  return out;
}

}  // namespace bimrock
