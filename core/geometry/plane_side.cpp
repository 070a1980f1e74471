#include "core/geometry/plane_side.h"

#include "core/geometry/exact_dyadic.h"

#if defined(__FAST_MATH__)
#error "plane_side_sign's filter relies on IEEE-754 rounding: do not build it with -ffast-math"
#endif

namespace tecido::detail {

int plane_side_sign_exact(const BoundedPlane& plane, const Vec3& p) {
  if (!p.allFinite() || !plane.position.allFinite() || !plane.normal.allFinite()) {
    const double s = plane.normal.dot(p - plane.position);
    return (s > 0.0) - (s < 0.0);
  }
  Dyadic s;
  for (int k = 0; k < 3; ++k) s = s + Dyadic(plane.normal[k]) * (Dyadic(p[k]) - Dyadic(plane.position[k]));
  return s.sign();
}

}  // namespace tecido::detail
