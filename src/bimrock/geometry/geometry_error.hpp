#pragma once
/// @file The error a user causes with bad geometry (a self-intersecting outline, a hole outside
/// the domain, a joint set with zero spacing). The geometry layer sits below `model`, so it
/// cannot throw model's InputError; the case reader catches this one and adds file and line.
#include <stdexcept>
#include <string>

namespace bimrock {

/// Bad geometric input. `item` names the offending entry the way a case file does, e.g.
/// "domain.holes[1]" or "joint_sets[0].spacing"; what() reads "item: message".
class GeometryError : public std::invalid_argument {
 public:
  GeometryError(std::string item, const std::string& message)
      : std::invalid_argument(item + ": " + message), item_(std::move(item)), message_(message) {}

  [[nodiscard]] const std::string& item() const { return item_; }
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  std::string item_;
  std::string message_;
};

}  // namespace bimrock
