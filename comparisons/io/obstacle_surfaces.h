#pragma once
/// Obstacles as triangle meshes for drawing (frames of `tecido run --out`): each obstacle's
/// surface at a time t, in world coordinates. A sphere is drawn as a latitude-longitude mesh
/// (12 rings of 24 segments: a picture, not the sphere the engine tests against), a box as its 12
/// triangles (core/geometry/box_mesh.h), a mesh as itself at its pose.
#include "core/geometry/obstacle.h"

#include <array>
#include <vector>

namespace tecido::io {

struct SurfaceMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;  ///< 0-based into vertices
};

/// Every obstacle's surface at time t, in obstacle order.
std::vector<SurfaceMesh> obstacle_surfaces(const std::vector<Obstacle>& obstacles, double t);

}  // namespace tecido::io
