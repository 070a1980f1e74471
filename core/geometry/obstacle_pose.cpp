#include "core/geometry/obstacle_pose.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

Eigen::Matrix3d rotation_at(const Obstacle& o, double t) {
  const double w = o.angular_velocity.norm();
  if (!(w > 0.0)) return o.orientation;
  return Eigen::AngleAxisd(w * t, o.angular_velocity / w).toRotationMatrix() * o.orientation;
}

void keyframes_at(const Obstacle& o, double t, ObstaclePose& pose) {
  const auto& f = o.frames;
  const std::size_t nv = f.front().vertices.size();
  pose.vertices.resize(nv);
  pose.vertex_velocity.assign(nv, Vec3::Zero());
  if (!(t > f.front().time)) {
    pose.vertices = f.front().vertices;
    return;
  }
  if (!(t < f.back().time)) {
    pose.vertices = f.back().vertices;
    return;
  }
  // First frame whose time exceeds t; t lies in [f[k-1].time, f[k].time).
  const auto it = std::upper_bound(f.begin(), f.end(), t, [](double x, const ObstacleMeshFrame& fr) { return x < fr.time; });
  const std::size_t k = static_cast<std::size_t>(it - f.begin());
  const ObstacleMeshFrame &a = f[k - 1], &b = f[k];
  const double span = b.time - a.time, w = (t - a.time) / span;
  for (std::size_t i = 0; i < nv; ++i) {
    pose.vertices[i] = a.vertices[i] + w * (b.vertices[i] - a.vertices[i]);
    pose.vertex_velocity[i] = (b.vertices[i] - a.vertices[i]) / span;
  }
}

}  // namespace

void obstacle_pose_at(const Obstacle& o, double t, ObstaclePose& pose) {
  pose.time = t;
  pose.center = o.center + t * o.velocity;
  pose.rotation = rotation_at(o, t);
  if (o.kind != ObstacleKind::Mesh) return;
  if (!o.frames.empty()) {
    keyframes_at(o, t, pose);
    return;
  }
  pose.vertex_velocity.clear();
  pose.vertices.resize(o.vertices.size());
  if (!o.moving()) {
    pose.vertices = o.vertices;
    return;
  }
  const Eigen::Matrix3d& r = pose.rotation;  // the mesh's orientation is the identity at t = 0
  for (std::size_t i = 0; i < o.vertices.size(); ++i) pose.vertices[i] = pose.center + r * (o.vertices[i] - o.center);
}

Vec3 obstacle_surface_velocity(const Obstacle& o, const ObstaclePose& pose, const Vec3& x, int triangle,
                               const Vec3& bary) {
  if (o.kind == ObstacleKind::Mesh && !o.frames.empty()) {
    if (triangle < 0 || pose.vertex_velocity.empty()) return Vec3::Zero();
    const auto& t = o.triangles[static_cast<std::size_t>(triangle)];
    return bary[0] * pose.vertex_velocity[t[0]] + bary[1] * pose.vertex_velocity[t[1]] +
           bary[2] * pose.vertex_velocity[t[2]];
  }
  return o.velocity + o.angular_velocity.cross(x - pose.center);
}

}  // namespace tecido
