#pragma once
/// A core Scene as the flat arrays of the plug-in ABI's tecido_scene (include/tecido/plugin.h):
/// positions, velocities, inverse masses, springs (ends, stiffness, rest length), gravity, linear
/// drag, the step and the feature bits. The arrays own their storage; view() points into them.
#include "core/scene/scene.h"
#include <tecido/plugin.h>

#include <cstdint>
#include <vector>

namespace tecido::outside {

struct SceneArrays {
  std::vector<double> positions, velocities, inverse_masses;
  std::vector<std::uint32_t> spring_ends;
  std::vector<double> spring_stiffness, spring_rest_length;
  double gravity[3] = {0, 0, 0};
  double linear_drag = 0.0;
  double dt = 0.0;
  std::uint64_t features = 0;

  /// The ABI struct pointing into these arrays (valid while this object lives, unchanged).
  tecido_scene view() const;
};

SceneArrays scene_arrays(const Scene& scene);

/// Flat 3n doubles back into points.
std::vector<Vec3> points_from_flat(const std::vector<double>& flat);

}  // namespace tecido::outside
