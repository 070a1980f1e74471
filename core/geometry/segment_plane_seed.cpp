#include "core/geometry/segment_plane_seed.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace tecido {

namespace {

/// Liang-Barsky clip of the 2-D segment (a0,b0) + t (da,db), t in [0,1], against the closed box
/// |a| <= hx, |b| <= hy. Returns the entering t, or nothing when the segment misses the box.
std::optional<double> clip_in_rectangle(double a0, double da, double b0, double db, double hx, double hy) {
  double t_enter = 0.0, t_leave = 1.0;
  auto clip = [&](double p, double q) {  // p t <= q
    if (p == 0.0) return q >= 0.0;
    const double r = q / p;
    if (p < 0.0) {
      t_enter = std::max(t_enter, r);
    } else {
      t_leave = std::min(t_leave, r);
    }
    return t_enter <= t_leave;
  };
  if (!clip(-da, a0 + hx) || !clip(da, hx - a0) || !clip(-db, b0 + hy) || !clip(db, hy - b0)) return std::nullopt;
  return t_enter;
}

}  // namespace

SegmentPlaneHit segment_plane_seed(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2) {
  // Positions relative to the plane (DETECTACOLISÃO's first step), projected on its three axes.
  const Vec3 d1 = p1 - plane.position;
  const Vec3 d2 = p2 - plane.position;
  const Vec3 right = plane.right();
  const double s1 = plane.normal.dot(d1), s2 = plane.normal.dot(d2);
  const double a1 = plane.forward.dot(d1), a2 = plane.forward.dot(d2);
  const double b1 = right.dot(d1), b2 = right.dot(d2);
  const double hx = plane.half_extents.x(), hy = plane.half_extents.y();

  SegmentPlaneHit out;
  if ((s1 > 0.0 && s2 > 0.0) || (s1 < 0.0 && s2 < 0.0)) return out;  // same side: no crossing
  if (s1 == 0.0 && s2 == 0.0) {                                      // the segment lies in the plane
    if (auto t = clip_in_rectangle(a1, a2 - a1, b1, b2 - b1, hx, hy)) {
      out.hit = true;
      out.t = *t;
    }
    return out;
  }
  // Different sides, or exactly one end point on the plane: one crossing point.
  const double t = s1 == 0.0 ? 0.0 : (s2 == 0.0 ? 1.0 : s1 / (s1 - s2));
  const double a = s1 == 0.0 ? a1 : (s2 == 0.0 ? a2 : a1 + t * (a2 - a1));
  const double b = s1 == 0.0 ? b1 : (s2 == 0.0 ? b2 : b1 + t * (b2 - b1));
  if (std::abs(a) <= hx && std::abs(b) <= hy) {
    out.hit = true;
    out.t = t;
  }
  return out;
}

}  // namespace tecido
