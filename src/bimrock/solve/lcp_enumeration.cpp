#include <bimrock/solve/lcp_enumeration.hpp>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>

#include <Eigen/LU>

namespace bimrock {
namespace {

/// Calls visit(z) for each basis solution, fewest active rows first, until it returns false.
/// Returns the number of bases tried.
template <typename Visit>
int for_each_basis_solution(const LcpProblem& p, const EnumerationOptions& o, Visit visit) {
  check_lcp(p);
  const Eigen::Index n = p.size();
  if (n > o.max_size) {
    throw std::invalid_argument("LCP enumeration: " + std::to_string(n) + " rows is too many");
  }
  std::vector<std::uint32_t> masks(std::size_t{1} << n);
  for (std::size_t s = 0; s < masks.size(); ++s)
    masks[s] = static_cast<std::uint32_t>(s);
  std::stable_sort(masks.begin(), masks.end(), [](std::uint32_t a, std::uint32_t b) {
    return std::popcount(a) < std::popcount(b);
  });
  int tried = 0;
  for (const std::uint32_t mask : masks) {
    ++tried;
    std::vector<Eigen::Index> a;
    for (Eigen::Index i = 0; i < n; ++i) {
      if (mask & (std::uint32_t{1} << i))
        a.push_back(i);
    }
    Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
    if (!a.empty()) {
      const Eigen::MatrixXd m_aa = p.m(a, a);
      Eigen::FullPivLU<Eigen::MatrixXd> lu(m_aa);
      lu.setThreshold(o.singular_tolerance);
      if (!lu.isInvertible())
        continue;
      z(a) = lu.solve(Eigen::VectorXd(-p.q(a)));
    }
    if (measure(p, z).worst_relative() > o.tolerance)
      continue;
    if (!visit(z))
      break;
  }
  return tried;
}

}  // namespace

std::vector<Eigen::VectorXd> enumerate_lcp_solutions(const LcpProblem& problem,
                                                     const EnumerationOptions& options) {
  std::vector<Eigen::VectorXd> found;
  for_each_basis_solution(problem, options, [&](const Eigen::VectorXd& z) {
    // Degenerate problems reach the same z from several bases (z_i = 0 with i active).
    const bool seen = std::any_of(found.begin(), found.end(), [&](const Eigen::VectorXd& f) {
      return (f - z).cwiseAbs().maxCoeff() <=
             options.tolerance * std::max(1.0, z.cwiseAbs().maxCoeff());
    });
    if (!seen)
      found.push_back(z);
    return true;
  });
  return found;
}

LcpResult LcpEnumeration::solve(const LcpProblem& problem, const Eigen::VectorXd* /*warm*/) {
  std::optional<Eigen::VectorXd> solution;
  const int tried = for_each_basis_solution(problem, options_, [&](const Eigen::VectorXd& z) {
    solution = z;
    return false;  // the first is the one with the fewest active rows
  });
  if (solution)
    return make_lcp_result(problem, LcpStatus::solved, *solution, tried);
  return make_lcp_result(problem, LcpStatus::no_solution, Eigen::VectorXd::Zero(problem.size()),
                         tried);
}

}  // namespace bimrock
