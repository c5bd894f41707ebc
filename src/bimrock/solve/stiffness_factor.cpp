#include <bimrock/solve/stiffness_factor.hpp>

#include <stdexcept>

namespace bimrock {

CholmodStiffnessFactor::CholmodStiffnessFactor(const SparseMatrix& lower) : lower_(lower) {}

bool CholmodStiffnessFactor::factorize() {
  k_.analyze(lower_, 6);
  return k_.factorize(lower_);
}

std::unique_ptr<CondensedStiffness> CholmodStiffnessFactor::condense(
    const CondensedStiffness& whole, const std::vector<char>& region) {
  k_.analyze_last(lower_, 6, region);
  if (!k_.factorize(lower_))
    throw std::logic_error("CholmodStiffnessFactor: K, positive definite before, is not now");
  return std::make_unique<CondensedStiffness>(whole, k_, 1, false);
}

}  // namespace bimrock
