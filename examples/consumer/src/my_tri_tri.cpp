// The user's triangle-triangle test: each edge of one triangle against the other triangle
// (Moller-Trumbore), in plain floating point with a small tolerance. It is the kind of test the
// harness's adversarial families are built to catch (coplanar pairs, touching, slivers).
#include "my_engine.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <cmath>

namespace {

using V = Eigen::Vector3d;

V corner(const double* t, int i) { return V(t[3 * i], t[3 * i + 1], t[3 * i + 2]); }

bool segment_hits_triangle(const V& p, const V& q, const V& a, const V& b, const V& c) {
  const double eps = 1e-12;
  const V dir = q - p, e1 = b - a, e2 = c - a;
  const V h = dir.cross(e2);
  const double det = e1.dot(h);
  if (std::abs(det) < eps) return false;  // parallel (coplanar pairs are not handled)
  const double f = 1.0 / det;
  const V s = p - a;
  const double u = f * s.dot(h);
  if (u < -eps || u > 1.0 + eps) return false;
  const V qv = s.cross(e1);
  const double v = f * dir.dot(qv);
  if (v < -eps || u + v > 1.0 + eps) return false;
  const double t = f * e2.dot(qv);
  return t >= -eps && t <= 1.0 + eps;
}

bool some_edge_hits(const double* x, const double* y) {
  for (int i = 0; i < 3; ++i)
    if (segment_hits_triangle(corner(x, i), corner(x, (i + 1) % 3), corner(y, 0), corner(y, 1), corner(y, 2)))
      return true;
  return false;
}

}  // namespace

int my_tri_tri(const double a[9], const double b[9]) { return some_edge_hits(a, b) || some_edge_hits(b, a) ? 1 : 0; }

tecido_engine my_tri_tri_engine() {
  tecido_engine e{};
  e.name = "my-tri-tri";
  e.flags = TECIDO_ENGINE_THREAD_SAFE;
  e.tri_tri = &my_tri_tri;
  return e;
}
