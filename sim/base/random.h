#pragma once
// Seeded random numbers that are bit-identical on every platform: std::mt19937_64 is
// fully specified by the standard; the distributions here are written out so that no
// library-defined algorithm enters the data.

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace tactip {

/// SplitMix64 finaliser: derives well-mixed independent seeds from (seed, stream).
inline std::uint64_t DeriveSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

/// Deterministic generator with uniform and normal draws.
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : gen_(seed) {}
  /// Uniform in [0, 1) with 53 random bits.
  double Uniform() { return static_cast<double>(gen_() >> 11) * 0x1.0p-53; }
  /// Uniform in [lo, hi).
  double Uniform(double lo, double hi) { return lo + (hi - lo) * Uniform(); }
  /// Standard normal by the Box-Muller transform (one value per call; the second is
  /// cached).
  double Normal() {
    if (has_cached_) {
      has_cached_ = false;
      return cached_;
    }
    double u1 = Uniform();
    while (u1 <= 0.0) u1 = Uniform();
    const double u2 = Uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    cached_ = r * std::sin(2.0 * std::numbers::pi * u2);
    has_cached_ = true;
    return r * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 gen_;
  double cached_ = 0.0;
  bool has_cached_ = false;
};

}  // namespace tactip
