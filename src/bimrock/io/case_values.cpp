#include <bimrock/io/case_values.hpp>

#include <cmath>

#include <fmt/core.h>

namespace bimrock::case_file {

double positive(const Value& v) {
  const double d = v.number();
  if (d <= 0.0)
    v.fail("must be positive");
  return d;
}

/// A point [x, y] that is a position in the model [m]: each coordinate within kMaxCoordinate.
Vec2 location(const Value& v) {
  const Vec2 p = v.point();
  if (std::abs(p.x()) > kMaxCoordinate || std::abs(p.y()) > kMaxCoordinate) {
    v.fail(fmt::format("coordinates must lie within +-{:g} m, not [{:g}, {:g}]", kMaxCoordinate,
                       p.x(), p.y()));
  }
  return p;
}

/// A number whose magnitude is at most `max` (in `unit`): stiffnesses and loads far beyond any
/// rock or structure overflow the stiffness matrix or the solution, so they are refused.
double bounded(const Value& v, double max, const char* unit, const char* why) {
  const double d = v.number();
  if (std::abs(d) > max)
    v.fail(fmt::format("must be at most {:g} {} in magnitude ({})", max, unit, why));
  return d;
}

/// A point or vector [x, y] each of whose components is bounded(max).
Vec2 bounded_vector(const Value& v, double max, const char* unit, const char* why) {
  const Vec2 p = v.point();
  if (std::abs(p.x()) > max || std::abs(p.y()) > max) {
    v.fail(fmt::format("each component must be at most {:g} {} in magnitude ({})", max, unit, why));
  }
  return p;
}

/// A non-empty name (material, monitor).
std::string name(const Value& v) {
  std::string s = v.text();
  if (s.empty())
    v.fail("must not be empty");
  return s;
}

/// An angle in degrees, 0 <= angle < 90.
double angle_deg(const Value& v) {
  const double a = v.number();
  if (a < 0.0 || a >= 90.0)
    v.fail("must be an angle in degrees, 0 <= angle < 90");
  return a;
}

double non_negative(const Value& v) {
  const double d = v.number();
  if (d < 0.0)
    v.fail("must be >= 0");
  return d;
}

/// A whole number >= 0 for a random seed.
std::uint64_t seed(const Value& v) {
  const int s = v.integer();
  if (s < 0)
    v.fail("must be a whole number >= 0");
  return static_cast<std::uint64_t>(s);
}

}  // namespace bimrock::case_file
