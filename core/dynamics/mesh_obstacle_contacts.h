#pragma once
/// A particle against a mesh obstacle's triangles over one interval of the contact loop
/// (obstacle_contacts.h): every triangle is two-sided, like a bounded plane (seed section 3.1.1),
/// and the particle remembers which side of each triangle's plane it is on. Sides are exact:
/// orient3d_sign (orient_predicates.h) of the triangle's corners and the point. A triangle is
/// tested only when the particle does not end the interval strictly on its remembered side; then
/// core's continuous vertex-face test (ccd/ccd.h: zero false negatives) of the particle's segment
/// against the triangle moving linearly from its start to its end pose decides, and gives the
/// time. Swept boxes (the mesh's, then the triangle's) reject far pairs first.
#include "core/geometry/obstacle_pose.h"

#include <array>
#include <cstdint>

namespace tecido {

/// Side of x with respect to the plane of triangle t of the pose: orient3d_sign(a, b, c, x),
/// +1 on the side opposite the normal (b - a) x (c - a), -1 on the normal's side, 0 on it.
int triangle_side(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& x);

/// The side a particle at x with velocity v and free acceleration a starts on: triangle_side, or
/// when that is 0 the side it comes from (against v, else against a), else +1.
std::int8_t initial_triangle_side(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& x, const Vec3& v,
                                  const Vec3& a);

/// Unit normal of triangle t pointing to the remembered side `side` (the particle's side).
Vec3 triangle_normal_towards(const ObstaclePose& pose, const std::array<int, 3>& t, int side);

struct MeshHit {
  int triangle = -1;  ///< -1: no hit
  double s = 2.0;     ///< time of impact as a fraction of the interval
};

/// The earliest triangle the segment x0 -> x1 touches while the mesh moves from p0 to p1,
/// skipping triangles with rest[f] set and those the particle ends strictly on the remembered
/// side of (side[f]); with first_only, the first triangle found (any_hit's early exit).
MeshHit mesh_earliest_hit(const Obstacle& o, const ObstaclePose& p0, const ObstaclePose& p1, const Vec3& x0,
                          const Vec3& x1, const std::int8_t* side, const std::uint8_t* rest, bool first_only);

/// x placed on triangle f of `pose` at barycentric weights `bary`, then moved along the normal
/// towards `side` by ulps until it is on that side or on the plane, exactly.
Vec3 place_on_triangle(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& bary, int side);

/// Unclamped barycentric weights of x's projection on the plane of triangle t (all >= 0: the
/// projection lies in the closed triangle).
Vec3 triangle_projection_barycentric(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& x);

}  // namespace tecido
