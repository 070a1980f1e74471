#pragma once
/// Spheres and boxes are solid: a free particle may not start inside one. The check both doors
/// to a scene make (the scene file's reader, comparisons/io/obstacle_json.h, and the public Scene
/// of include/tecido/simulation.h).
#include "core/geometry/obstacle.h"
#include "core/geometry/segment_box.h"
#include "core/geometry/segment_sphere.h"

#include <cstdint>
#include <vector>

namespace tecido {

/// The first free (not pinned) particle of x strictly inside sphere or box `o` at its pose at
/// t = 0; -1 when none (and always for a mesh).
inline int first_free_particle_inside(const Obstacle& o, const std::vector<Vec3>& x,
                                      const std::vector<std::uint8_t>& pinned) {
  if (o.kind == ObstacleKind::Mesh) return -1;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (pinned[i]) continue;
    const Vec3 d = x[i] - o.center;
    const bool inside = o.kind == ObstacleKind::Sphere ? inside_sphere(d, o.radius)
                                                       : inside_box(o.orientation.transpose() * d, o.half_extents);
    if (inside) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace tecido
