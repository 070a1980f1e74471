#pragma once
/// What a scene asks for beyond particles, springs, gravity and linear drag: the features an
/// outside dynamics engine must model or refuse (include/tecido/plugin.h, TECIDO_FEATURE_*). The
/// plug-in door passes them as bits, the process door as names beside the scene's JSON.
#include "core/scene/scene.h"

#include <cstdint>
#include <string>
#include <vector>

namespace tecido::outside {

/// TECIDO_FEATURE_* bits of `scene`.
std::uint64_t feature_bits(const Scene& scene);

/// The names of `bits`, in bit order: "wind", "planes", "spring_damping", "self_collision",
/// "obstacles", "edge_contacts" (unknown bits as "feature-bit-N").
std::vector<std::string> feature_names(std::uint64_t bits);

}  // namespace tecido::outside
