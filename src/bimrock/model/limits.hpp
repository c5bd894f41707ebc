#pragma once
/// @file The bound on coordinates, and the message of a case that would exceed one of its limits
/// (CaseLimits, the case file's `limits`): the estimate, the limit, what to change, and how to
/// raise the limit.
#include <sstream>
#include <string>

namespace bimrock {

/// The largest coordinate magnitude [m] of a case file's points and a mesh's nodes. Exact
/// geometry (CGAL) squares and multiplies coordinates; near 1e308 that overflows and CGAL
/// crashes, so coordinates are bounded where they are read.
inline constexpr double kMaxCoordinate = 1e9;

/// "would generate about <estimate> <what>, more than limits.<key> = <limit>: <advice>, or
/// raise the limit (limits: {<key>: ...})".
inline std::string limit_message(double estimate, double limit, const std::string& key,
                                 const std::string& what, const std::string& advice) {
  std::ostringstream s;
  s.precision(3);
  s << "would generate about " << estimate << ' ' << what << ", more than limits." << key << " = ";
  s.precision(10);
  s << limit << ": " << advice << ", or raise the limit (limits: {" << key << ": ...})";
  return s.str();
}

}  // namespace bimrock
