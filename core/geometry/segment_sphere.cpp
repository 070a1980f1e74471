#include "core/geometry/segment_sphere.h"

#include <algorithm>
#include <cmath>

namespace tecido {

SphereEntry segment_enters_sphere(const Vec3& r0, const Vec3& r1, double radius) {
  const bool end_inside = inside_sphere(r1, radius);
  const Vec3 d = r1 - r0;
  const double a = d.squaredNorm(), b = r0.dot(d), c = r0.squaredNorm() - radius * radius;
  // Inside where a s^2 + 2 b s + c < 0.
  if (!(a > 0.0)) return SphereEntry{c < 0.0 || end_inside, 0.0};
  const double disc = b * b - a * c;
  if (!(disc > 0.0)) return SphereEntry{end_inside, 1.0};  // misses or grazes the ball
  const double q = -(b + std::copysign(std::sqrt(disc), b));
  double s1 = q / a, s2 = c / q;  // the two roots (Vieta), q != 0 since disc > 0
  if (s1 > s2) std::swap(s1, s2);
  if (s1 < 1.0 && s2 > 0.0) return SphereEntry{true, std::clamp(s1, 0.0, 1.0)};
  return SphereEntry{end_inside, end_inside ? std::clamp(s1, 0.0, 1.0) : 0.0};
}

Vec3 place_on_sphere(const Vec3& r, double radius) {
  const double n = r.norm();
  const Vec3 u = n > 0.0 && std::isfinite(n) ? Vec3(r / n) : Vec3::UnitZ();
  Vec3 x = radius * u;
  double step = 0x1p-52 * radius;
  for (int tries = 0; tries < 64 && inside_sphere(x, radius); ++tries) {
    x += step * u;
    step *= 2.0;
  }
  return x;
}

}  // namespace tecido
