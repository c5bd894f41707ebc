#pragma once
/// @file Typed, checked access to a parsed YAML document. Every value knows where it came from
/// (file, 1-based line, and the item path a user recognises, e.g. "blocks[3].vertices[1]"), and
/// every accessor throws InputError naming that place when the value has the wrong shape.
/// yaml-cpp itself is lenient (it keeps duplicate keys, converts quoted strings to numbers and
/// accepts .nan); the checks that make a case file strict live here.
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <yaml-cpp/yaml.h>

#include <bimrock/geometry/vec2.hpp>
#include <bimrock/model/errors.hpp>

namespace bimrock::yaml {

struct Entry;

/// A YAML node together with its place in the file.
class Value {
 public:
  /// @param file borrowed: must outlive the value (the reader's file name).
  /// @param line 1-based (0: unknown).
  Value(YAML::Node node, std::string_view file, int line, std::string item)
      : node_(std::move(node)), file_(file), line_(line), item_(std::move(item)) {}

  [[nodiscard]] int line() const { return line_; }
  [[nodiscard]] const std::string& item() const { return item_; }
  [[nodiscard]] SourceRef ref() const { return {line_, item_}; }
  [[nodiscard]] std::string_view file() const { return file_; }
  [[nodiscard]] const YAML::Node& node() const { return node_; }

  /// Throws InputError(file, line, item, message).
  [[noreturn]] void fail(const std::string& message) const;

  /// A plain (unquoted) scalar that is a finite number; rejects .nan and .inf.
  [[nodiscard]] double number() const;
  /// A plain scalar that is a whole number fitting an int (1, not 1.0).
  [[nodiscard]] int integer() const;
  /// true / false (YAML 1.1 spellings such as yes / no are accepted too).
  [[nodiscard]] bool boolean() const;
  /// Any scalar, as written.
  [[nodiscard]] std::string text() const;
  /// [x, y]: a list of two finite numbers.
  [[nodiscard]] Vec2 point() const;
  /// The elements of a list, each with item "<item>[k]" and its own line.
  [[nodiscard]] std::vector<Value> list() const;
  /// The entries of a map in file order, each value with item "<item>.<key>" and the line of its
  /// key. Rejects keys that are not scalars and keys given twice.
  [[nodiscard]] std::vector<Entry> entries() const;
  /// The item path of a child of this value: "<item>.<key>", or "<key>" at the top level.
  [[nodiscard]] std::string child_item(std::string_view key) const;

 private:
  [[nodiscard]] const std::string& scalar(const char* what) const;

  YAML::Node node_;
  std::string_view file_;
  int line_;
  std::string item_;
};

struct Entry {
  std::string key;
  Value value;
};

/// A map whose keys are checked against a fixed set when it is opened: an unknown key, a key
/// given twice or a value that is not a map throws, naming the key and its line.
class Map {
 public:
  /// @param allowed the keys this map may hold, in the order they are listed in error messages.
  Map(const Value& map, std::vector<std::string_view> allowed);

  [[nodiscard]] const Value& self() const { return self_; }
  [[nodiscard]] bool has(std::string_view key) const { return find(key).has_value(); }
  [[nodiscard]] std::optional<Value> find(std::string_view key) const;
  /// The value of a required key; throws "required key missing" at the map's line when absent.
  [[nodiscard]] Value at(std::string_view key) const;

  /// Optional typed values with a default.
  [[nodiscard]] double number_or(std::string_view key, double fallback) const;
  [[nodiscard]] int integer_or(std::string_view key, int fallback) const;
  [[nodiscard]] bool boolean_or(std::string_view key, bool fallback) const;
  [[nodiscard]] std::string text_or(std::string_view key, const std::string& fallback) const;

 private:
  Value self_;
  std::vector<Entry> entries_;
};

}  // namespace bimrock::yaml
