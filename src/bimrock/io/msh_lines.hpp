#pragma once
/// @file Internal to the gmsh reader (gmsh_mesh.hpp; not part of the public API): the lines of an
/// MSH file read one at a time (Cursor), and the words of one line with typed access (Words).
/// Every error they raise names the file, the line and the item being read (InputError).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace bimrock::msh {

/// The whitespace-separated words of one line, with typed access that names what was expected.
class Words {
 public:
  Words(std::string_view line, const std::string& file, int number);

  [[nodiscard]] std::size_t size() const { return words_.size(); }
  [[nodiscard]] std::string_view operator[](std::size_t k) const { return words_[k]; }

  [[noreturn]] void fail(const std::string& item, const std::string& message) const;

  /// Exactly n words (or at least n when `at_least`).
  void expect_count(std::size_t n, const std::string& item, const char* what,
                    bool at_least = false) const;

  [[nodiscard]] std::int64_t integer(std::size_t k, const std::string& item,
                                     const char* what) const;

  /// An int-sized whole number >= 0 (a count or an entity tag).
  [[nodiscard]] int count(std::size_t k, const std::string& item, const char* what) const;

  [[nodiscard]] double real(std::size_t k, const std::string& item, const char* what) const;

 private:
  [[nodiscard]] std::string_view at(std::size_t k, const std::string& item, const char* what) const;

  std::vector<std::string_view> words_;
  const std::string& file_;
  int number_;
};

/// The lines of the file, read one at a time; blank lines are skipped, "\r\n" ends are accepted.
class Cursor {
 public:
  Cursor(std::string_view text, const std::string& file) : text_(text), file_(file) {}

  [[nodiscard]] const std::string& file() const { return file_; }
  [[nodiscard]] int line() const { return line_; }

  /// The next non-blank line, or nothing at the end of the file.
  std::optional<std::string_view> next_or_end();

  /// The next non-blank line of section `section`; the end of the file there is an error.
  std::string_view next(const std::string& section);

  Words words(const std::string& section);

  /// The line that must close `section` ("$EndNodes" for "$Nodes").
  void expect_end(const std::string& section);

  /// Skips a section the reader does not need, up to its end line.
  void skip(const std::string& section);

  [[noreturn]] void fail(const std::string& item, const std::string& message) const;

 private:
  std::string_view text_;
  std::string file_;
  std::size_t pos_ = 0;
  int line_ = 0;
};

}  // namespace bimrock::msh
