#pragma once
/// A bounded (rectangular) plane, seed section 3.1.1: position (the rectangle's centre),
/// unit normal, unit forward (in the plane), right = normal x forward, and half extents
/// along forward and right. Two-sided: a particle may hit it from either side.
#include "core/geometry/types.h"

#include <cmath>

namespace tecido {

struct BoundedPlane {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();    ///< unit length
  Vec3 forward = Vec3::UnitX();   ///< unit length, orthogonal to normal
  Vec2 half_extents = Vec2::Ones();  ///< half sizes along forward (x) and right (y), >= 0
  /// Friction quotient mu in [0, 1] used by static contacts: a large tangential velocity is
  /// scaled by (1 - mu) each step in static contact, a small one is zeroed (0 = frictionless).
  double friction = 0.0;

  /// right = normal x forward, so (forward, right, normal) is right-handed.
  Vec3 right() const { return normal.cross(forward); }

  /// Signed distance of p along the normal (positive on the normal's side).
  double side(const Vec3& p) const { return normal.dot(p - position); }

  /// True when p, assumed to lie on the plane, is inside the closed rectangle:
  /// |forward.(p - position)| <= hx and |right.(p - position)| <= hy (the seed's test with
  /// the missing lower bound added, docs/design.md section 1).
  bool contains_projection(const Vec3& p) const {
    const Vec3 d = p - position;
    return std::abs(forward.dot(d)) <= half_extents.x() && std::abs(right().dot(d)) <= half_extents.y();
  }
};

/// Makes a plane from possibly unnormalised normal and forward; forward is orthogonalised
/// against the normal by Gram-Schmidt applied twice ("twice is enough", Parlett 1980: one pass
/// leaves a residual of eps / sin(angle), 1e-7 for a forward 1e-9 rad off the normal; the second
/// pass brings it to eps). Vectors that are already unit length and orthogonal (to within a few
/// ulps) are kept exactly as given, so a plane that is written out at full precision and read
/// back is the same plane, bit for bit. The caller validates that neither is zero and that they
/// are not parallel.
inline BoundedPlane make_bounded_plane(const Vec3& position, const Vec3& normal, const Vec3& forward,
                                       const Vec2& half_extents, double friction) {
  constexpr double kTol = 1e-14;
  auto unit = [](const Vec3& v) {
    const double n2 = v.squaredNorm();
    return std::abs(n2 - 1.0) <= kTol ? v : Vec3(v / std::sqrt(n2));
  };
  BoundedPlane p;
  p.position = position;
  p.normal = unit(normal);
  Vec3 f = unit(forward);
  if (!(std::abs(p.normal.dot(f)) <= kTol)) {
    f -= p.normal * p.normal.dot(f);
    f -= p.normal * p.normal.dot(f);
    f = unit(f);
  }
  p.forward = f;
  p.half_extents = half_extents;
  p.friction = friction;
  return p;
}

}  // namespace tecido
