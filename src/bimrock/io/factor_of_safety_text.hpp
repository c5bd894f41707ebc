#pragma once
/// @file The console line that says what the search for the factor of safety found: a bracket,
/// a bound with the reason the search ended there, or the largest F tried.
#include <string>

#include <bimrock/analysis/factor_of_safety.hpp>

namespace bimrock {

/// One line, without its newline, starting "FACTOR OF SAFETY (strength reduction): ".
[[nodiscard]] std::string factor_of_safety_text(const FactorOfSafety& f);

}  // namespace bimrock
