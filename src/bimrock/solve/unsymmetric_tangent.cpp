#include <bimrock/solve/unsymmetric_tangent.hpp>

#include <cmath>
#include <utility>

#include <Eigen/UmfPackSupport>
#include <unsupported/Eigen/IterativeSolvers>

namespace bimrock {

namespace {

/// GMRES on the tangent: at most this many iterations (without restarts: it converges in 28-47
/// on the associated form's tangent), to this relative residual of the preconditioned equations.
constexpr int kGmresIterations = 80;
constexpr double kGmresTolerance = 1e-12;
/// The residual of the tangent's own equations that a result of GMRES must meet, relative to
/// the size of their terms.
constexpr double kTangentResidual = 1e-10;

/// A LinearSolve as Eigen's iterative solvers take a preconditioner.
class SolvePreconditioner {
 public:
  SolvePreconditioner() = default;
  explicit SolvePreconditioner(const LinearSolve* solve) : solve_(solve) {}
  template <typename Matrix>
  SolvePreconditioner& analyzePattern(const Matrix& /*a*/) {
    return *this;
  }
  template <typename Matrix>
  SolvePreconditioner& factorize(const Matrix& /*a*/) {
    return *this;
  }
  template <typename Matrix>
  SolvePreconditioner& compute(const Matrix& /*a*/) {
    return *this;
  }
  template <typename Rhs>
  [[nodiscard]] Eigen::VectorXd solve(const Rhs& b) const {
    return (*solve_)(Eigen::VectorXd(b));
  }
  [[nodiscard]] Eigen::ComputationInfo info() const { return Eigen::Success; }

 private:
  const LinearSolve* solve_ = nullptr;
};

}  // namespace

// UMFPACK's solves read the matrix again (iterative refinement), and Eigen's wrapper keeps
// only a view of it: the tangent lives beside its factor.
struct UnsymmetricTangentEquations::Lu {
  CholmodMatrix tangent;
  Eigen::UmfPackLU<CholmodMatrix> lu;
};

UnsymmetricTangentEquations::UnsymmetricTangentEquations(const SplitLcp& lcp, const SpdSolver& s,
                                                         Preconditioner preconditioner)
    : SplitLcpEquations(lcp, s),
      s_full_(lcp.k_lower->selfadjointView<Eigen::Lower>()),
      preconditioner_(std::move(preconditioner)),
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
  if (preconditioner_) {
    const std::optional<LinearSolve> near = preconditioner_(active);
    if (near && solve_iteratively(active, locals, damping, check, *near, out)) {
      ++iterative_solves_;
      return out;
    }
  }
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

bool UnsymmetricTangentEquations::solve_iteratively(const std::vector<Eigen::Index>& active,
                                                    const std::vector<Local>& locals,
                                                    const Damping& damping, Check check,
                                                    const LinearSolve& preconditioner,
                                                    Solution& out) const {
  Eigen::GMRES<CholmodMatrix, SolvePreconditioner> gmres;
  gmres.set_restart(kGmresIterations);
  gmres.setMaxIterations(kGmresIterations);
  gmres.setTolerance(kGmresTolerance);
  gmres.compute(lu_->tangent);
  gmres.preconditioner() = SolvePreconditioner(&preconditioner);
  // GMRES measures the residual of the preconditioned equations, which a poor preconditioner
  // can make small: the tangent's own residual r = T x - b is measured too, against the size of
  // the terms that sum to it (|T| |x| + |b|).
  const CholmodMatrix magnitudes = lu_->tangent.cwiseAbs();
  bool converged = true;
  Solution tried = out;
  const double worst = solve_through(
      active, locals, damping, check,
      [&](const Eigen::VectorXd& rhs) {
        Eigen::VectorXd x = gmres.solve(rhs);
        const Eigen::VectorXd scale = magnitudes * x.cwiseAbs() + rhs.cwiseAbs();
        converged =
            converged && gmres.info() == Eigen::Success &&
            (lu_->tangent * x - rhs).cwiseAbs().maxCoeff() <= kTangentResidual * scale.maxCoeff();
        return x;
      },
      tried);
  if (!converged || !(worst <= kSolveAccuracy))
    return false;
  tried.regular = true;
  out = std::move(tried);
  return true;
}

}  // namespace bimrock
