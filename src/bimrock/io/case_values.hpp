#pragma once
/// @file The typed values the sections of a case file share (internal to the case reader):
/// positive, non-negative and bounded numbers, locations in the model, names, one of a fixed set
/// of names, angles, seeds, and lists and named maps of items. Each refuses a bad value with an
/// InputError naming its file, line and item. The functions are documented at their definitions
/// (case_values.cpp).
#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <bimrock/geometry/vec2.hpp>
#include <bimrock/io/yaml_value.hpp>
#include <bimrock/model/limits.hpp>

namespace bimrock::case_file {

using yaml::Entry;
using yaml::Map;
using yaml::Value;

double positive(const Value& v);
double non_negative(const Value& v);
Vec2 location(const Value& v);
double bounded(const Value& v, double max, const char* unit, const char* why);
Vec2 bounded_vector(const Value& v, double max, const char* unit, const char* why);
std::string name(const Value& v);
double angle_deg(const Value& v);
std::uint64_t seed(const Value& v);

constexpr double kMaxModulus = 1e15;    // [Pa]: 1000 times diamond's
constexpr double kMaxStiffness = 1e20;  // [Pa/m]: kn of a 1e15 Pa layer 10 um thick
constexpr double kMaxForce = 1e15;      // [N], and [Pa] for tractions
constexpr const char* kStiffer = "no rock or joint is stiffer; larger values overflow";
constexpr const char* kLarger = "larger loads overflow the displacements";

/// One of a fixed set of names, e.g. plane: strain | stress.
template <class E>
E choice(const Value& v, std::initializer_list<std::pair<std::string_view, E>> options) {
  const std::string s = v.text();
  std::string names;
  for (const auto& [name, value] : options) {
    if (s == name)
      return value;
    if (!names.empty())
      names.append(", ");
    names.append(name);
  }
  v.fail("unknown value '" + s + "' (allowed: " + names + ")");
}

template <class Read>
auto read_list(const Value& v, Read read) {
  std::vector<decltype(read(v))> out;
  for (const Value& element : v.list())
    out.push_back(read(element));
  return out;
}

/// A map name -> item (materials, joint_materials); names must not be empty.
template <class Read>
auto read_named(const Value& v, Read read) {
  std::vector<decltype(read(v.entries().front()))> out;
  for (const Entry& e : v.entries()) {
    if (e.key.empty())
      e.value.fail("a name must not be empty");
    out.push_back(read(e));
  }
  return out;
}

}  // namespace bimrock::case_file
