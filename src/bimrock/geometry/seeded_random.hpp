#pragma once
/// @file Reproducible random numbers: the same seed gives the same numbers on every standard
/// library. std::mt19937_64 is fully specified by the standard, but the std distributions are
/// not (libstdc++ and libc++ draw normal numbers differently), so the distributions are ours.
#include <cstdint>
#include <random>

namespace bimrock {

/// A seed derived from a base seed and a stream number (SplitMix64 finaliser), so that
/// independent streams (each joint set, each block to subdivide) do not share numbers.
std::uint64_t derive_seed(std::uint64_t seed, std::uint64_t stream);

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : engine_(seed) {}

  /// Uniform in [0, 1), from the top 53 bits of one 64-bit draw.
  double uniform01();
  /// Uniform in [a, b).
  double uniform(double a, double b) { return a + (b - a) * uniform01(); }
  /// Normal with the given mean and standard deviation (Marsaglia's polar method).
  /// @note bit-identical wherever std::log and std::sqrt are (sqrt is exact by IEEE 754; glibc's
  ///       log is correctly rounded in practice).
  double normal(double mean, double std_dev);

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;  ///< the polar method makes two numbers per accepted pair
  double spare_ = 0.0;
};

}  // namespace bimrock
