#pragma once
/// The fixed benchmark input for triangle-triangle tests: pairs of triangles with vertices
/// uniform in the unit cube, from std::mt19937_64 seeded 42, each double made from the top
/// 53 bits of one draw ((x >> 11) * 2^-53, not std::uniform_real_distribution, whose output
/// differs between standard libraries). Draw order: a0.x a0.y a0.z a1.x ... a2.z b0.x ... b2.z.
/// Shared by the core and the reference-engine benchmarks so they time identical pairs.
#include "core/geometry/types.h"

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace tecido::bench {

struct TrianglePair {
  Triangle a, b;
};

inline constexpr std::size_t kDefaultPairCount = 100000;
inline constexpr std::uint64_t kDefaultPairSeed = 42;

inline std::vector<TrianglePair> random_unit_cube_pairs(std::size_t count = kDefaultPairCount,
                                                        std::uint64_t seed = kDefaultPairSeed) {
  std::mt19937_64 rng(seed);
  auto unit = [&rng] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::vector<TrianglePair> pairs(count);
  for (TrianglePair& pair : pairs) {
    for (Triangle* t : {&pair.a, &pair.b}) {
      for (Vec3& v : *t) {
        const double x = unit();
        const double y = unit();
        const double z = unit();
        v = Vec3(x, y, z);
      }
    }
  }
  return pairs;
}

/// The same pairs, generated once per process.
inline const std::vector<TrianglePair>& default_random_pairs() {
  static const std::vector<TrianglePair> pairs = random_unit_cube_pairs();
  return pairs;
}

}  // namespace tecido::bench
