#pragma once
// The axis-aligned rectangle [x0, x1] x [y0, y1] [m], counter-clockwise from (x0, y0).
#include <bimrock/geometry/polygon.hpp>

namespace bimrock::testing {

inline Polygon rectangle(double x0, double y0, double x1, double y1) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}};
}

}  // namespace bimrock::testing
