#pragma once
/// A rigid or keyframed obstacle a cloth can hit (seed section 2.3: "collisions with polygonal
/// objects and spheres"): a sphere, a box or a triangle mesh, static or with prescribed motion.
/// Obstacles are kinematic: they push particles and are never pushed back.
///
/// Motion (docs/design.md section 3, scene key "obstacles"):
///  - translation: centre(t) = center + velocity t;
///  - rotation about the obstacle's centre at a constant world-frame angular velocity w:
///    R(t) = exp(t [w]x) R0 (R0 = the box's orientation, identity for spheres and meshes);
///  - a mesh may instead have keyframes: vertices interpolated linearly between consecutive
///    frames (times increasing), held at the first frame before it and at the last after it.
/// A mesh's centre (the pivot of its rotation) is given by the scene or is the centroid of its
/// vertices. Poses at a time are computed by obstacle_pose.h.
#include "core/geometry/types.h"

#include <array>
#include <optional>
#include <vector>

namespace tecido {

enum class ObstacleKind { Sphere, Box, Mesh };

/// "sphere", "box", "mesh" (the scene file's keys).
inline const char* obstacle_kind_name(ObstacleKind k) {
  return k == ObstacleKind::Sphere ? "sphere" : (k == ObstacleKind::Box ? "box" : "mesh");
}

/// One keyframe of a deforming mesh: every vertex's position at `time` [s].
struct ObstacleMeshFrame {
  double time = 0.0;
  std::vector<Vec3> vertices;
};

struct Obstacle {
  ObstacleKind kind = ObstacleKind::Sphere;
  Vec3 center = Vec3::Zero();          ///< sphere or box centre; a mesh's pivot [m] at t = 0
  double radius = 0.0;                 ///< sphere [m], > 0
  Vec3 half_extents = Vec3::Zero();    ///< box, along its local axes [m], >= 0
  Eigen::Matrix3d orientation = Eigen::Matrix3d::Identity();  ///< box: local axes as columns (R0)
  std::vector<Vec3> vertices;          ///< mesh, world positions at t = 0 [m]
  std::vector<std::array<int, 3>> triangles;  ///< mesh, 0-based vertex indices, no degenerate face
  std::vector<ObstacleMeshFrame> frames;      ///< mesh keyframes (empty: rigid motion below)
  Vec3 velocity = Vec3::Zero();          ///< constant translation [m/s]
  Vec3 angular_velocity = Vec3::Zero();  ///< about the centre, world frame [rad/s]
  /// Friction quotient mu in [0, 1] of static contacts, as for planes (default 0, frictionless).
  double friction = 0.0;
  /// Elastic quotient of contacts with this obstacle; when absent, each particle's own k is used
  /// (as for planes, which have none).
  std::optional<double> elasticity;

  bool moving() const {
    return !frames.empty() || velocity != Vec3::Zero() || angular_velocity != Vec3::Zero();
  }
};

}  // namespace tecido
