#pragma once
/// Where an obstacle is at time t, and how fast its surface moves there (obstacle.h describes the
/// motion). World position of a local point q: center + rotation q. For a mesh, `vertices` holds
/// the world positions at t (rigid motion applied to the t = 0 vertices about the pivot, or the
/// keyframes interpolated).
#include "core/geometry/obstacle.h"

#include <vector>

namespace tecido {

struct ObstaclePose {
  double time = 0.0;
  Vec3 center = Vec3::Zero();
  Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
  std::vector<Vec3> vertices;         ///< mesh only: world positions at `time`
  std::vector<Vec3> vertex_velocity;  ///< mesh with keyframes only: d vertex / dt at `time`

  /// Local coordinates of a world point: rotation^T (x - center).
  Vec3 to_local(const Vec3& x) const { return rotation.transpose() * (x - center); }
  Vec3 to_world(const Vec3& q) const { return center + rotation * q; }
};

/// The pose of `o` at time t, written into `pose` (its vectors are reused; no allocation once
/// sized). Rotation: Eigen's AngleAxis of angle |w| t about w / |w|, times the box's orientation.
/// Keyframes: linear interpolation between the two frames around t (velocity: their difference
/// over their time span), the first frame before it, the last after it (velocity 0).
void obstacle_pose_at(const Obstacle& o, double t, ObstaclePose& pose);

/// Velocity [m/s] of the obstacle's surface at world point x: velocity + w x (x - center) for
/// rigid motion; for a keyframed mesh, the vertex velocities of `triangle` interpolated with the
/// barycentric weights `bary` of x in it.
Vec3 obstacle_surface_velocity(const Obstacle& o, const ObstaclePose& pose, const Vec3& x, int triangle = -1,
                               const Vec3& bary = Vec3::Zero());

}  // namespace tecido
