#pragma once
// Angles: the tests write them in degrees, the code takes radians; `x * kDeg` converts.
#include <cmath>

namespace bimrock::testing {

inline constexpr double kDeg = M_PI / 180.0;  // [rad/deg]

}  // namespace bimrock::testing
