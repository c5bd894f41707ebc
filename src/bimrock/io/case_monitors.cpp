/// @file The monitors section: named points whose displacement is recorded; a monitor's name is
/// part of file names.
#include <bimrock/io/case_sections.hpp>

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <fmt/core.h>

namespace bimrock::case_file {

namespace {

/// A name that becomes part of a file name (a monitor's plot_<name>.png): no folder separator,
/// no control character, not "." or "..", and short enough for a file name with its prefix and
/// suffix (most file systems allow 255 bytes).
std::string file_name_part(const Value& v) {
  std::string s = name(v);
  constexpr std::size_t kMaxBytes = 200;
  if (s.size() > kMaxBytes) {
    v.fail(fmt::format("is {} bytes long: a name is part of a file name, at most {} bytes",
                       s.size(), kMaxBytes));
  }
  for (const char c : s) {
    if (c == '/' || c == '\\' || static_cast<unsigned char>(c) < 0x20 || c == 0x7F) {
      v.fail("must not contain '/', '\\' or control characters: a name is part of a file name");
    }
  }
  if (s == "." || s == "..")
    v.fail("must not be '.' or '..': a name is part of a file name");
  return s;
}

}  // namespace

std::vector<MonitorSpec> read_monitors(const Value& v) {
  std::vector<MonitorSpec> monitors;
  std::map<std::string, std::size_t> named;  // each name's monitor (not a search: 1e5 monitors)
  for (const Value& element : v.list()) {
    const Map m = open(element, "monitors[]");
    const Value n = m.at("name");
    MonitorSpec monitor{file_name_part(n), location(m.at("at")), element.ref()};
    // Monitors are looked up by name (results columns, displacement control): names are unique.
    if (const auto [other, fresh] = named.emplace(monitor.name, monitors.size()); !fresh) {
      const SourceRef& first = monitors[other->second].source;
      n.fail("monitor name '" + monitor.name + "' already used by " + first.item + " (line " +
             std::to_string(first.line) + ")");
    }
    monitors.push_back(std::move(monitor));
  }
  return monitors;
}

}  // namespace bimrock::case_file
