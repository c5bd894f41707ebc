#include <bimrock/io/factor_of_safety_text.hpp>

#include <fmt/core.h>

namespace bimrock {

std::string factor_of_safety_text(const FactorOfSafety& f) {
  const std::string head = "FACTOR OF SAFETY (strength reduction): ";
  const char* undecided = "could not be solved accurately, nor shown to fail";
  // Below 1 the search lowers F until the stages carry; an undecided trial ends it early.
  if (f.collapse && f.lower == 0.0 && f.undecided)
    return head + fmt::format(
                      "F < {:.4f}: the stages fail there, and the next trial, with the "
                      "strengths raised further, {}",
                      f.collapse->failed, undecided);
  if (f.collapse && f.lower == 0.0)
    return head + fmt::format(
                      "F < {:.4f}: the stages fail even with the strengths multiplied by "
                      "factor_of_safety.largest",
                      f.collapse->failed);
  if (f.collapse)
    return head +
           fmt::format(
               "F between {:.4f} (carried) and {:.4f} (fails); {} yield modes in its mechanism "
               "(summary.json, fos_mechanism.png){}",
               f.lower, f.collapse->failed, f.collapse->mechanism.size(),
               f.undecided ? fmt::format("; a trial inside {}, so the bracket is wider than its "
                                         "tolerance",
                                         undecided)
                           : std::string());
  if (f.undecided)
    return head + fmt::format("F >= {:.4f}; the next step {}", f.lower, undecided);
  return head + fmt::format("F >= {:.4f}, the largest tried (factor_of_safety.largest)", f.lower);
}

}  // namespace bimrock
