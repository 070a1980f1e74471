#include "comparisons/engines/outside/scene_features.h"

#include <tecido/plugin.h>

namespace tecido::outside {

std::uint64_t feature_bits(const Scene& scene) {
  std::uint64_t bits = 0;
  if (scene.forces.wind) bits |= TECIDO_FEATURE_WIND;
  if (!scene.planes.empty()) bits |= TECIDO_FEATURE_PLANES;
  for (const Spring& s : scene.forces.springs)
    if (s.damping != 0.0) bits |= TECIDO_FEATURE_SPRING_DAMPING;
  if (scene.self_collision) bits |= TECIDO_FEATURE_SELF_COLLISION;
  return bits;
}

std::vector<std::string> feature_names(std::uint64_t bits) {
  static const char* const names[] = {"wind", "planes", "spring_damping", "self_collision", "obstacles", "edge_contacts"};
  std::vector<std::string> out;
  for (int b = 0; b < 64; ++b) {
    if (!(bits >> b & 1u)) continue;
    out.push_back(b < 6 ? names[b] : "feature-bit-" + std::to_string(b));
  }
  return out;
}

}  // namespace tecido::outside
