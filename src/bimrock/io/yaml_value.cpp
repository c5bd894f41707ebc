#include <bimrock/io/yaml_value.hpp>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <utility>

#include <fmt/core.h>

namespace bimrock::yaml {
namespace {

/// What a node is, for "must be X, not Y" messages.
std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Null:
    case YAML::NodeType::Undefined:
      return "nothing (the value is missing)";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Scalar:
      break;
  }
  return "'" + node.Scalar() + "'";
}

/// 1-based line of a node, or `fallback` when yaml-cpp has no mark for it.
int line_of(const YAML::Node& node, int fallback) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? fallback : mark.line + 1;
}

/// The offset of the first byte of `s` that is not part of well-formed UTF-8, or npos.
std::size_t invalid_utf8(const std::string& s) {
  std::size_t i = 0;
  while (i < s.size()) {
    const auto c = static_cast<unsigned char>(s[i]);
    std::size_t n = 0;
    unsigned lo = 0x80;
    unsigned hi = 0xBF;
    if (c < 0x80)
      n = 0;
    else if (c >= 0xC2 && c <= 0xDF)
      n = 1;
    else if (c >= 0xE0 && c <= 0xEF) {
      n = 2;
      lo = c == 0xE0 ? 0xA0 : 0x80;  // no overlong forms
      hi = c == 0xED ? 0x9F : 0xBF;  // no surrogates
    } else if (c >= 0xF0 && c <= 0xF4) {
      n = 3;
      lo = c == 0xF0 ? 0x90 : 0x80;
      hi = c == 0xF4 ? 0x8F : 0xBF;
    } else {
      return i;
    }
    if (n > 0 && i + n >= s.size())
      return i;  // truncated sequence
    for (std::size_t k = 1; k <= n; ++k) {
      const auto b = static_cast<unsigned char>(s[i + k]);
      if (b < (k == 1 ? lo : 0x80) || b > (k == 1 ? hi : 0xBF))
        return i;
    }
    i += n + 1;
  }
  return std::string::npos;
}

std::string joined(const std::vector<std::string_view>& words) {
  std::string s;
  for (std::string_view w : words) {
    if (!s.empty())
      s += ", ";
    s += w;
  }
  return s;
}

}  // namespace

void Value::fail(const std::string& message) const {
  throw InputError(std::string(file_), line_, item_, message);
}

std::string Value::child_item(std::string_view key) const {
  std::string s = item_;
  if (!s.empty())
    s += '.';
  s += key;
  return s;
}

const std::string& Value::scalar(const char* what) const {
  if (!node_.IsScalar())
    fail(std::string("must be ") + what + ", not " + describe(node_));
  return node_.Scalar();
}

double Value::number() const {
  const std::string& s = scalar("a number");
  // yaml-cpp converts a quoted "10" too; a quoted value is a string in YAML, so reject it.
  if (node_.Tag() != "?")
    fail("must be a number, not the string '" + s + "'");
  double d = 0.0;
  if (!YAML::convert<double>::decode(node_, d))
    fail("must be a number, not '" + s + "'");
  if (!std::isfinite(d))
    fail("must be a finite number, not '" + s + "'");
  return d;
}

int Value::integer() const {
  const std::string& s = scalar("a whole number");
  int i = 0;
  if (node_.Tag() != "?" || !YAML::convert<int>::decode(node_, i))
    fail("must be a whole number, not '" + s + "'");
  return i;
}

bool Value::boolean() const {
  const std::string& s = scalar("true or false");
  bool b = false;
  if (node_.Tag() != "?" || !YAML::convert<bool>::decode(node_, b))
    fail("must be true or false, not '" + s + "'");
  return b;
}

std::string Value::text() const {
  const std::string& s = scalar("a string");
  // Names and titles reach file names, JSON and pictures, which all take UTF-8: a byte of
  // another encoding (Latin-1 0xFC for u-umlaut) is rejected here rather than written escaped.
  if (const std::size_t at = invalid_utf8(s); at != std::string::npos) {
    fail(
        fmt::format("is not valid UTF-8 (byte 0x{:02X} at position {}): save the case file as "
                    "UTF-8",
                    static_cast<unsigned char>(s[at]), at + 1));
  }
  return s;
}

Vec2 Value::point() const {
  if (!node_.IsSequence() || node_.size() != 2)
    fail("must be a point [x, y] (a list of two numbers), not " + describe(node_));
  const std::vector<Value> xy = list();
  return {xy[0].number(), xy[1].number()};
}

std::vector<Value> Value::list() const {
  if (!node_.IsSequence())
    fail("must be a list [...], not " + describe(node_));
  std::vector<Value> elements;
  elements.reserve(node_.size());
  for (const YAML::Node& element : node_) {
    elements.emplace_back(element, file_, line_of(element, line_),
                          item_ + "[" + std::to_string(elements.size()) + "]");
  }
  return elements;
}

std::vector<Entry> Value::entries() const {
  if (!node_.IsMap())
    fail("must be a map {key: value, ...}, not " + describe(node_));
  std::vector<Entry> entries;
  entries.reserve(node_.size());
  // Each key's entry, to find a repeated key in O(1) (a map of 1e5 materials took 48 s when
  // each key was compared with all the earlier ones).
  std::unordered_map<std::string, std::size_t> seen;
  for (auto it = node_.begin(); it != node_.end(); ++it) {
    const int line = line_of(it->first, line_);
    if (!it->first.IsScalar())
      throw InputError(std::string(file_), line, item_,
                       "a key must be a plain name, not " + describe(it->first));
    const std::string& key = it->first.Scalar();
    // yaml-cpp keeps both entries of a repeated key (and lookups see only the first): catch it.
    if (const auto [same, fresh] = seen.emplace(key, entries.size()); !fresh) {
      throw InputError(std::string(file_), line, child_item(key),
                       "key given twice (first on line " +
                           std::to_string(entries[same->second].value.line()) + ")");
    }
    // The line of the key, not of the value: a block-style value starts on the next line.
    entries.push_back({key, Value(it->second, file_, line, child_item(key))});
  }
  return entries;
}

Map::Map(const Value& map, std::vector<std::string_view> allowed)
    : self_(map), entries_(map.entries()) {
  for (const Entry& e : entries_) {
    if (std::find(allowed.begin(), allowed.end(), e.key) == allowed.end()) {
      throw InputError(std::string(map.file()), e.value.line(), e.value.item(),
                       "unknown key '" + e.key + "' (allowed here: " + joined(allowed) + ")");
    }
  }
}

std::optional<Value> Map::find(std::string_view key) const {
  for (const Entry& e : entries_) {
    if (e.key == key)
      return e.value;
  }
  return std::nullopt;
}

Value Map::at(std::string_view key) const {
  std::optional<Value> v = find(key);
  if (!v) {
    throw InputError(std::string(self_.file()), self_.line(), self_.child_item(key),
                     "required key '" + std::string(key) + "' is missing");
  }
  return *v;
}

double Map::number_or(std::string_view key, double fallback) const {
  const std::optional<Value> v = find(key);
  return v ? v->number() : fallback;
}

int Map::integer_or(std::string_view key, int fallback) const {
  const std::optional<Value> v = find(key);
  return v ? v->integer() : fallback;
}

bool Map::boolean_or(std::string_view key, bool fallback) const {
  const std::optional<Value> v = find(key);
  return v ? v->boolean() : fallback;
}

std::string Map::text_or(std::string_view key, const std::string& fallback) const {
  const std::optional<Value> v = find(key);
  return v ? v->text() : fallback;
}

}  // namespace bimrock::yaml
