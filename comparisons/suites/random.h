#pragma once
/// Seeded random numbers that are the same on every platform: std::mt19937_64 is specified
/// bit for bit, and the conversion to double is done here (std::uniform_real_distribution is
/// not portable across standard libraries).
#include "core/geometry/types.h"

#include <cstdint>
#include <random>

namespace tecido::suites {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  /// Uniform in [0, 1) with 53 random bits.
  double unit() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * unit(); }
  /// Uniform integer in [0, n).
  std::uint64_t below(std::uint64_t n) { return g_() % n; }
  Vec3 in_box(double lo, double hi) { return Vec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)); }
  /// A uniformly distributed unit vector (normalised Gaussian-free: rejection in the cube).
  Vec3 unit_vector() {
    for (;;) {
      const Vec3 v = in_box(-1.0, 1.0);
      const double n = v.norm();
      if (n > 1e-3 && n <= 1.0) return v / n;
    }
  }
  std::uint64_t next() { return g_(); }

 private:
  std::mt19937_64 g_;
};

/// A seed for sub-stream `index` of `seed` (SplitMix64 of the pair), so case k's inputs do not
/// depend on how many cases came before or on which thread runs it.
inline std::uint64_t substream(std::uint64_t seed, std::uint64_t index) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (index + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

}  // namespace tecido::suites
