#include "core/geometry/tri_tri_rotation.h"

namespace tecido {
namespace {

/// Some edge of `a` crosses the closed triangle `b` (seed fig. 18).
bool edges_cross(const Triangle& a, const Triangle& b) {
  const Vec3 v12 = b[1] - b[0], v23 = b[2] - b[1], v31 = b[0] - b[2];
  const Vec3 n = v12.cross(b[2] - b[0]);
  for (int i = 0; i < 3; ++i) {
    const Vec3& s = a[i];
    const Vec3& e = a[(i + 1) % 3];
    const double ds = n.dot(s - b[0]);
    const double de = n.dot(e - b[0]);
    if ((ds > 0.0 && de > 0.0) || (ds < 0.0 && de < 0.0)) continue;  // same side
    if (ds == de) continue;  // in the plane (or n = 0): no crossing point
    const Vec3 pc = s + (e - s) * (ds / (ds - de));
    const double c1 = n.dot(v12.cross(pc - b[0]));
    const double c2 = n.dot(v23.cross(pc - b[1]));
    const double c3 = n.dot(v31.cross(pc - b[2]));
    if ((c1 >= 0.0 && c2 >= 0.0 && c3 >= 0.0) || (c1 <= 0.0 && c2 <= 0.0 && c3 <= 0.0)) {
      return true;
    }
  }
  return false;
}

}  // namespace

bool tri_tri_rotation(const Triangle& t1, const Triangle& t2) {
  return edges_cross(t1, t2) || edges_cross(t2, t1);
}

}  // namespace tecido
