#include "comparisons/io/obstacle_surfaces.h"

#include "core/geometry/box_mesh.h"
#include "core/geometry/obstacle_pose.h"

#include <cmath>

namespace tecido::io {

namespace {

constexpr int kRings = 12, kSegments = 24;

SurfaceMesh sphere_surface(const ObstaclePose& pose, double r) {
  SurfaceMesh m;
  m.vertices.push_back(pose.to_world(Vec3(0, 0, r)));  // north pole
  for (int i = 1; i < kRings; ++i) {
    const double th = M_PI * i / kRings;
    for (int j = 0; j < kSegments; ++j) {
      const double ph = 2.0 * M_PI * j / kSegments;
      m.vertices.push_back(pose.to_world(r * Vec3(std::sin(th) * std::cos(ph), std::sin(th) * std::sin(ph), std::cos(th))));
    }
  }
  m.vertices.push_back(pose.to_world(Vec3(0, 0, -r)));  // south pole
  const int south = static_cast<int>(m.vertices.size()) - 1;
  auto ring = [](int i, int j) { return 1 + (i - 1) * kSegments + (j % kSegments); };
  for (int j = 0; j < kSegments; ++j) {
    m.triangles.push_back({0, ring(1, j), ring(1, j + 1)});
    m.triangles.push_back({south, ring(kRings - 1, j + 1), ring(kRings - 1, j)});
    for (int i = 1; i + 1 < kRings; ++i) {
      m.triangles.push_back({ring(i, j), ring(i + 1, j), ring(i + 1, j + 1)});
      m.triangles.push_back({ring(i, j), ring(i + 1, j + 1), ring(i, j + 1)});
    }
  }
  return m;
}

}  // namespace

std::vector<SurfaceMesh> obstacle_surfaces(const std::vector<Obstacle>& obstacles, double t) {
  std::vector<SurfaceMesh> out;
  ObstaclePose pose;
  for (const Obstacle& o : obstacles) {
    obstacle_pose_at(o, t, pose);
    if (o.kind == ObstacleKind::Sphere) {
      out.push_back(sphere_surface(pose, o.radius));
    } else if (o.kind == ObstacleKind::Box) {
      SurfaceMesh m;
      for (const Vec3& q : box_corners(o.half_extents)) m.vertices.push_back(pose.to_world(q));
      m.triangles.assign(kBoxTriangles.begin(), kBoxTriangles.end());
      out.push_back(std::move(m));
    } else {
      out.push_back(SurfaceMesh{pose.vertices, o.triangles});
    }
  }
  return out;
}

}  // namespace tecido::io
