#pragma once
// The benchmark model: model/reference_cases.hpp's brick mass under gravity.
#include <bimrock/model/reference_cases.hpp>

namespace bimrock::bench {

inline CaseSpec brick_mass_case(int n_blocks) {
  return bimrock::brick_mass_case(n_blocks);
}

}  // namespace bimrock::bench
