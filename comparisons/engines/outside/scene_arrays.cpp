#include "comparisons/engines/outside/scene_arrays.h"

#include "comparisons/engines/outside/scene_features.h"

namespace tecido::outside {

tecido_scene SceneArrays::view() const {
  tecido_scene s{};
  s.particle_count = inverse_masses.size();
  s.positions = positions.data();
  s.velocities = velocities.data();
  s.inverse_masses = inverse_masses.data();
  s.spring_count = spring_stiffness.size();
  s.spring_ends = spring_ends.data();
  s.spring_stiffness = spring_stiffness.data();
  s.spring_rest_length = spring_rest_length.data();
  for (int c = 0; c < 3; ++c) s.gravity[c] = gravity[c];
  s.linear_drag = linear_drag;
  s.dt = dt;
  s.features = features;
  return s;
}

SceneArrays scene_arrays(const Scene& scene) {
  SceneArrays a;
  const Particles& p = scene.particles;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      a.positions.push_back(p.x[i][c]);
      a.velocities.push_back(p.v[i][c]);
    }
    a.inverse_masses.push_back(p.pinned[i] ? 0.0 : p.inv_mass[i]);
  }
  for (const Spring& s : scene.forces.springs) {
    a.spring_ends.push_back(static_cast<std::uint32_t>(s.i));
    a.spring_ends.push_back(static_cast<std::uint32_t>(s.j));
    a.spring_stiffness.push_back(s.stiffness);
    a.spring_rest_length.push_back(s.rest_length);
  }
  if (scene.forces.gravity)
    for (int c = 0; c < 3; ++c) a.gravity[c] = (*scene.forces.gravity)[c];
  a.linear_drag = scene.forces.air_drag.value_or(0.0);
  a.dt = scene.dt;
  a.features = feature_bits(scene);
  return a;
}

std::vector<Vec3> points_from_flat(const std::vector<double>& flat) {
  std::vector<Vec3> out(flat.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = Vec3(flat[3 * i], flat[3 * i + 1], flat[3 * i + 2]);
  return out;
}

}  // namespace tecido::outside
