// The user's continuous-collision test: the four points are coplanar when the cubic
// f(t) = det(p1 - p0, p2 - p0, p3 - p0) vanishes; f is sampled at 65 times, every sign change (or
// zero) is bisected to 1e-13, and at the root the primitives are tested with a tolerance of 1e-9
// (vertex inside the triangle; the two segments within 1e-9 of each other). The earliest root that
// passes is the time of impact. It misses tangential contacts between two samples and motion that
// stays coplanar, which the harness's families contain on purpose.
#include "my_engine.h"

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <array>
#include <cmath>

namespace {

using V = Eigen::Vector3d;
using Points = std::array<V, 4>;

Points at(const double t0[12], const double t1[12], double t) {
  Points p;
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) p[i][c] = (1.0 - t) * t0[3 * i + c] + t * t1[3 * i + c];
  return p;
}

double coplanarity(const Points& p) { return (p[1] - p[0]).cross(p[2] - p[0]).dot(p[3] - p[0]); }

bool vertex_in_face(const Points& p) {
  const double eps = 1e-9;
  const V e1 = p[2] - p[1], e2 = p[3] - p[1], d = p[0] - p[1];
  const double a = e1.dot(e1), b = e1.dot(e2), c = e2.dot(e2), den = a * c - b * b;
  if (den <= 0.0) return false;
  const double u = (c * e1.dot(d) - b * e2.dot(d)) / den, v = (a * e2.dot(d) - b * e1.dot(d)) / den;
  return u >= -eps && v >= -eps && u + v <= 1.0 + eps;
}

bool edges_meet(const Points& p) {
  const double eps = 1e-9;
  const V d1 = p[1] - p[0], d2 = p[3] - p[2], r = p[0] - p[2];
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r), c = d1.dot(r), b = d1.dot(d2), den = a * e - b * b;
  if (a <= 0.0 || e <= 0.0) return false;
  double s = den > 0.0 ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0 || t > 1.0) {
    t = std::clamp(t, 0.0, 1.0);
    s = std::clamp((b * t - c) / a, 0.0, 1.0);
  }
  return ((p[0] + s * d1) - (p[2] + t * d2)).norm() <= eps;
}

int sampled(const double t0[12], const double t1[12], double* toi, bool (*meets)(const Points&)) {
  const int samples = 64;
  double ta = 0.0, fa = coplanarity(at(t0, t1, 0.0));
  for (int k = 1; k <= samples; ++k) {
    const double tb = double(k) / samples, fb = coplanarity(at(t0, t1, tb));
    if (fa == 0.0 || fa * fb < 0.0) {
      double lo = ta, hi = tb, flo = fa;
      while (hi - lo > 1e-13 && flo != 0.0) {
        const double mid = 0.5 * (lo + hi), fm = coplanarity(at(t0, t1, mid));
        if (flo * fm <= 0.0) hi = mid;
        else lo = mid, flo = fm;
      }
      const double root = flo == 0.0 ? lo : hi;
      if (meets(at(t0, t1, root))) {
        *toi = root;
        return 1;
      }
    }
    ta = tb, fa = fb;
  }
  if (fa == 0.0 && meets(at(t0, t1, 1.0))) {
    *toi = 1.0;
    return 1;
  }
  return 0;
}

}  // namespace

int my_ccd_vertex_face(const double t0[12], const double t1[12], double* toi) {
  return sampled(t0, t1, toi, &vertex_in_face);
}

int my_ccd_edge_edge(const double t0[12], const double t1[12], double* toi) { return sampled(t0, t1, toi, &edges_meet); }

tecido_engine my_ccd_engine() {
  tecido_engine e{};
  e.name = "my-ccd";
  e.flags = TECIDO_ENGINE_THREAD_SAFE;
  e.ccd_vertex_face = &my_ccd_vertex_face;
  e.ccd_edge_edge = &my_ccd_edge_edge;
  return e;
}
