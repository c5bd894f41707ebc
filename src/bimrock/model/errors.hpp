#pragma once
/// @file The two kinds of error a user can cause. Both are thrown, caught once in main().
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace bimrock {

/// Where an item of the case file came from: its 1-based line (0 when unknown) and a short
/// name a user recognises, e.g. "blocks[3]" or "joint material 'bedding'".
struct SourceRef {
  int line = 0;
  std::string item;
};

/// Bad input: a malformed file, an unknown key, an invalid value or shape.
class InputError : public std::runtime_error {
 public:
  InputError(std::string file, int line, std::string item, const std::string& message)
      : std::runtime_error(format(file, line, item, message)),
        file_(std::move(file)),
        line_(line),
        item_(std::move(item)),
        message_(message) {}
  InputError(const std::string& file, const SourceRef& ref, const std::string& message)
      : InputError(file, ref.line, ref.item, message) {}

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& item() const { return item_; }
  [[nodiscard]] const std::string& message() const { return message_; }

 private:
  static std::string format(const std::string& file, int line, const std::string& item,
                            const std::string& message) {
    std::ostringstream s;  // (not operator+: GCC 12 raises a false -Wrestrict on it)
    s << (file.empty() ? std::string("<input>") : file);
    if (line > 0)
      s << ':' << line;
    s << ": ";
    if (!item.empty())
      s << item << ": ";
    s << message;
    return s.str();
  }
  std::string file_;
  int line_;
  std::string item_;
  std::string message_;
};

/// A model that is well-formed but cannot be analysed, e.g. blocks that can move freely.
/// Carries the 0-based indices of the blocks concerned.
class ModelError : public std::runtime_error {
 public:
  ModelError(const std::string& message, std::vector<int> blocks)
      : std::runtime_error(message), blocks_(std::move(blocks)) {}
  [[nodiscard]] const std::vector<int>& blocks() const { return blocks_; }

 private:
  std::vector<int> blocks_;
};

}  // namespace bimrock
