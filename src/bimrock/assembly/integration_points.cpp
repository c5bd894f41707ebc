#include <bimrock/assembly/integration_points.hpp>

#include <cmath>

namespace bimrock {

std::array<IntegrationPoint, 2> integration_points(const Segment& s, Integration rule) {
  const double half = 0.5 * s.length();
  if (rule == Integration::lobatto)
    return {{{s.a, half}, {s.b, half}}};
  const double g = 0.5 / std::sqrt(3.0);
  return {{{s.at(0.5 - g), half}, {s.at(0.5 + g), half}}};
}

}  // namespace bimrock
