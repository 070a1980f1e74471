#include "core/geometry/ccd/closest_params.h"

#include <algorithm>

namespace tecido {

namespace {

double dot(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double clamp01(double s) { return s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s); }
/// n / d in [0, 1], 0 when d is 0 (a zero-length edge: any parameter is as close).
double ratio01(double n, double d) { return d > 0.0 ? clamp01(n / d) : 0.0; }

/// |z - s e|^2 at the best s in [0, 1]; the parameter in s.
double closest_on_segment(const double e[3], const double z[3], double& s) {
  const double ee = dot(e, e);
  s = ee > 0.0 ? clamp01(dot(e, z) / ee) : 0.0;
  const double r[3] = {z[0] - s * e[0], z[1] - s * e[1], z[2] - s * e[2]};
  return dot(r, r);
}

/// Degenerate triangles: the nearest of the three edges a-b, a-c, b-c.
void closest_on_edges(const double x[3], const double y[3], const double z[3], double& u, double& v) {
  double s = 0.0;
  double best = closest_on_segment(x, z, s);  // a + s X
  u = s;
  v = 0.0;
  double d = closest_on_segment(y, z, s);  // a + s Y
  if (d < best) {
    best = d;
    u = 0.0;
    v = s;
  }
  const double bc[3] = {y[0] - x[0], y[1] - x[1], y[2] - x[2]};
  const double bz[3] = {z[0] - x[0], z[1] - x[1], z[2] - x[2]};
  d = closest_on_segment(bc, bz, s);  // b + s (c - b): u = 1 - s, v = s
  if (d < best) {
    u = 1.0 - s;
    v = s;
  }
}

}  // namespace

void ccd_closest_on_triangle(const double x[3], const double y[3], const double z[3], double& u, double& v) {
  // Ericson's region tests with ab = X, ac = Y, ap = Z, bp = Z - X, cp = Z - Y.
  const double d1 = dot(x, z), d2 = dot(y, z);
  u = v = 0.0;
  if (d1 <= 0.0 && d2 <= 0.0) return;  // vertex a
  const double bp[3] = {z[0] - x[0], z[1] - x[1], z[2] - x[2]};
  const double d3 = dot(x, bp), d4 = dot(y, bp);
  if (d3 >= 0.0 && d4 <= d3) {  // vertex b
    u = 1.0;
    return;
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {  // edge ab
    u = ratio01(d1, d1 - d3);  // d1 - d3 = |X|^2
    return;
  }
  const double cp[3] = {z[0] - y[0], z[1] - y[1], z[2] - y[2]};
  const double d5 = dot(x, cp), d6 = dot(y, cp);
  if (d6 >= 0.0 && d5 <= d6) {  // vertex c
    v = 1.0;
    return;
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {  // edge ac
    v = ratio01(d2, d2 - d6);  // d2 - d6 = |Y|^2
    return;
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {  // edge bc
    v = ratio01(d4 - d3, (d4 - d3) + (d5 - d6));  // the denominator is |Y - X|^2
    u = 1.0 - v;
    return;
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) {  // zero area (or rounding said so): the edges decide
    closest_on_edges(x, y, z, u, v);
    return;
  }
  u = clamp01(vb / sum);
  v = std::min(clamp01(vc / sum), 1.0 - u);
}

void ccd_closest_on_segments(const double x[3], const double y[3], const double z[3], double& u, double& v) {
  // Ericson's ClosestPtSegmentSegment with d1 = X, d2 = b1 - b0 = -Y, r = a0 - b0 = -Z.
  const double a = dot(x, x), e = dot(y, y);
  const double f = dot(y, z);         // d2 . r
  const double c = -dot(x, z);        // d1 . r
  u = v = 0.0;
  if (a <= 0.0 && e <= 0.0) return;
  if (a <= 0.0) {
    v = clamp01(f / e);
    return;
  }
  if (e <= 0.0) {
    u = clamp01(-c / a);
    return;
  }
  const double b = -dot(x, y);        // d1 . d2
  const double denom = a * e - b * b;
  u = denom > 0.0 ? clamp01((b * f - c * e) / denom) : 0.0;
  v = (b * u + f) / e;
  if (v < 0.0) {
    v = 0.0;
    u = clamp01(-c / a);
  } else if (v > 1.0) {
    v = 1.0;
    u = clamp01((b - c) / a);
  }
}

}  // namespace tecido
