#include "core/geometry/closest_points.h"

#include <algorithm>

namespace tecido {

Vec3 closest_triangle_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0.0 && d2 <= 0.0) return Vec3(1, 0, 0);
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0.0 && d4 <= d3) return Vec3(0, 1, 0);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
    const double v = d1 - d3 != 0.0 ? d1 / (d1 - d3) : 0.0;
    return Vec3(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0.0 && d5 <= d6) return Vec3(0, 0, 1);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
    const double w = d2 - d6 != 0.0 ? d2 / (d2 - d6) : 0.0;
    return Vec3(1 - w, 0, w);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0) {
    const double den = (d4 - d3) + (d5 - d6);
    const double w = den != 0.0 ? (d4 - d3) / den : 0.0;
    return Vec3(0, 1 - w, w);
  }
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return Vec3(1, 0, 0);  // degenerate: unreachable for a proper triangle
  const double v = vb / sum, w = vc / sum;
  return Vec3(1 - v - w, v, w);
}

Vec2 closest_segment_params(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.squaredNorm(), e = d2.squaredNorm(), f = d2.dot(r);
  if (a <= 0.0 && e <= 0.0) return Vec2(0, 0);
  if (a <= 0.0) return Vec2(0, std::clamp(f / e, 0.0, 1.0));
  const double c = d1.dot(r);
  if (e <= 0.0) return Vec2(std::clamp(-c / a, 0.0, 1.0), 0);
  const double b = d1.dot(d2), denom = a * e - b * b;
  double s = denom > 0.0 ? std::clamp((b * f - c * e) / denom, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) {
    t = 0.0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if (t > 1.0) {
    t = 1.0;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  return Vec2(s, t);
}

}  // namespace tecido
