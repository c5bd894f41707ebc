#pragma once
/// @file The message of a case that would exceed one of its limits (CaseLimits, the case
/// file's `limits`): the estimate, the limit, what to change, and how to raise the limit.
#include <sstream>
#include <string>

namespace bimrock {

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
