#include "core/dynamics/springs_through_obstacle.h"

#include "core/geometry/obstacle_pose.h"
#include "core/geometry/orient_predicates.h"
#include "core/geometry/segment_box.h"
#include "core/geometry/segment_sphere.h"

#include <algorithm>

namespace tecido {

namespace {

/// The segment p-q crosses triangle abc's interior: ends strictly on opposite sides of its plane,
/// the line strictly inside its three edges (Möller and Trumbore's test in exact signs).
bool crosses_triangle(const Vec3& p, const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const int sp = orient3d_sign(a, b, c, p), sq = orient3d_sign(a, b, c, q);
  if (sp == 0 || sq == 0 || sp == sq) return false;
  const int e0 = orient3d_sign(p, q, a, b), e1 = orient3d_sign(p, q, b, c), e2 = orient3d_sign(p, q, c, a);
  return e0 != 0 && e0 == e1 && e1 == e2;
}

bool through(const Obstacle& o, const ObstaclePose& pose, const Vec3& a, const Vec3& b) {
  if (o.kind == ObstacleKind::Box) return segment_box_depth(pose.to_local(a), pose.to_local(b), o.half_extents) > 0.0;
  if (o.kind == ObstacleKind::Sphere) {
    const Vec3 r0 = a - pose.center, d = b - a;
    const double dd = d.squaredNorm();
    const double s = dd > 0.0 ? std::clamp(-r0.dot(d) / dd, 0.0, 1.0) : 0.0;
    return inside_sphere(r0 + s * d, o.radius);
  }
  for (const auto& t : o.triangles)
    if (crosses_triangle(a, b, pose.vertices[t[0]], pose.vertices[t[1]], pose.vertices[t[2]])) return true;
  return false;
}

}  // namespace

bool segment_through_obstacle(const Obstacle& o, double t, const Vec3& a, const Vec3& b) {
  ObstaclePose pose;
  obstacle_pose_at(o, t, pose);
  return through(o, pose, a, b);
}

int springs_through_obstacle(const Obstacle& o, double t, const std::vector<Spring>& springs,
                             const std::vector<Vec3>& x) {
  ObstaclePose pose;
  obstacle_pose_at(o, t, pose);
  int n = 0;
  for (const Spring& sp : springs)
    if (through(o, pose, x[static_cast<std::size_t>(sp.i)], x[static_cast<std::size_t>(sp.j)])) ++n;
  return n;
}

}  // namespace tecido
