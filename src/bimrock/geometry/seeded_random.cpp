#include <bimrock/geometry/seeded_random.hpp>

#include <cmath>

namespace bimrock {

std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream) {
  // SplitMix64 (Steele, Lea and Flood 2014) applied to seed + stream * golden-ratio increment.
  std::uint64_t z = seed + (stream + 1) * 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

double SeededRandom::uniform01() {
  return static_cast<double>(engine_() >> 11) * 0x1.0p-53;
}

double SeededRandom::normal(double mean, double std_dev) {
  if (has_spare_) {
    has_spare_ = false;
    return mean + std_dev * spare_;
  }
  double u = 0.0;
  double v = 0.0;
  double s = 0.0;
  do {  // a point uniform in the unit disc, origin excluded
    u = uniform(-1.0, 1.0);
    v = uniform(-1.0, 1.0);
    s = u * u + v * v;
  } while (s >= 1.0 || s == 0.0);
  const double f = std::sqrt(-2.0 * std::log(s) / s);
  spare_ = v * f;
  has_spare_ = true;
  return mean + std_dev * u * f;
}

}  // namespace bimrock
