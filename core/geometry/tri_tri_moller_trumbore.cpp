#include "core/geometry/tri_tri_moller_trumbore.h"

namespace tecido {
namespace {

constexpr double kEpsilon = 1e-6;  // Möller & Trumbore 1997, "#define EPSILON 0.000001"

/// The paper's test with the triangle's edge vectors e1 = v1 - v0, e2 = v2 - v0 given.
inline bool moller_trumbore(const Vec3& o, const Vec3& dir, const Vec3& v0, const Vec3& e1,
                            const Vec3& e2) {
  const Vec3 pvec = dir.cross(e2);
  const double det = e1.dot(pvec);
  if (det > -kEpsilon && det < kEpsilon) return false;  // parallel to the plane
  const double inv_det = 1.0 / det;
  const Vec3 tvec = o - v0;
  const double u = tvec.dot(pvec) * inv_det;
  if (u < 0.0 || u > 1.0) return false;
  const Vec3 qvec = tvec.cross(e1);
  const double v = dir.dot(qvec) * inv_det;
  if (v < 0.0 || u + v > 1.0) return false;
  const double t = e2.dot(qvec) * inv_det;  // the distance along dir, in units of |dir|
  return t >= 0.0 && t <= 1.0;
}

bool some_edge_hits(const Triangle& a, const Triangle& b) {
  const Vec3 e1 = b[1] - b[0];
  const Vec3 e2 = b[2] - b[0];
  for (int i = 0; i < 3; ++i) {
    if (moller_trumbore(a[i], a[(i + 1) % 3] - a[i], b[0], e1, e2)) return true;
  }
  return false;
}

}  // namespace

bool segment_triangle_moller_trumbore(const Vec3& o, const Vec3& dir, const Triangle& t) {
  return moller_trumbore(o, dir, t[0], t[1] - t[0], t[2] - t[0]);
}

bool tri_tri_moller_trumbore(const Triangle& t1, const Triangle& t2) {
  return some_edge_hits(t1, t2) && some_edge_hits(t2, t1);
}

}  // namespace tecido
