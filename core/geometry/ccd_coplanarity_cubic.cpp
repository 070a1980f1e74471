#include "core/geometry/ccd_coplanarity_cubic.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

struct V3 {
  double x, y, z;
};

inline V3 load(const double* p) { return {p[0], p[1], p[2]}; }
inline V3 cross(const V3& a, const V3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
/// The permanent of the cross product: |a| x |b| with + in place of -.
inline V3 cross_abs(const V3& a, const V3& b) {
  return {std::fabs(a.y * b.z) + std::fabs(a.z * b.y), std::fabs(a.z * b.x) + std::fabs(a.x * b.z),
          std::fabs(a.x * b.y) + std::fabs(a.y * b.x)};
}
inline V3 add(const V3& a, const V3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline double dot(const V3& a, const V3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline double dot_abs(const V3& a, const V3& b) {
  return std::fabs(a.x) * b.x + std::fabs(a.y) * b.y + std::fabs(a.z) * b.z;
}

}  // namespace

void ccd_coplanarity_cubic(const CcdSystem& s, double f[4], CcdErrorBound& err) {
  const V3 x0 = load(s.d[0][CcdSystem::X]), x1 = load(s.d[1][CcdSystem::X]);
  const V3 y0 = load(s.d[0][CcdSystem::Y]), y1 = load(s.d[1][CcdSystem::Y]);
  const V3 z0 = load(s.d[0][CcdSystem::Z]), z1 = load(s.d[1][CcdSystem::Z]);
  const V3 c00 = cross(y0, z0), c11 = cross(y1, z1);
  const V3 sum = add(cross(y1, z0), cross(y0, z1));
  f[0] = dot(x0, c00);
  f[1] = (dot(x1, c00) + dot(x0, sum)) / 3.0;
  f[2] = (dot(x0, c11) + dot(x1, sum)) / 3.0;
  f[3] = dot(x1, c11);
  // First a cheap bound: every coefficient is an average of determinants whose six terms are
  // each at most mx my mz (the largest components of X, Y, Z over both times), so the
  // permanent is at most 6 mx my mz. When the coefficients clear it, that bound certifies the
  // cubic's sign; otherwise (near-coplanar motion) the permanents themselves are computed.
  double m[3] = {0.0, 0.0, 0.0};
  for (int v = 0; v < 3; ++v)
    for (int time = 0; time < 2; ++time)
      for (int c = 0; c < 3; ++c) m[v] = std::max(m[v], std::fabs(s.d[time][v][c]));
  err.e0 = 0x1p-49 * (6.0 * (1.0 + 0x1p-50)) * (m[0] * m[1] * m[2]) + 0x1p-900;
  const double lo = std::min(std::min(f[0], f[1]), std::min(f[2], f[3]));
  const double hi = std::max(std::max(f[0], f[1]), std::max(f[2], f[3]));
  if (!(lo > err.e0 || hi < -err.e0)) {
    const V3 p00 = cross_abs(y0, z0), p11 = cross_abs(y1, z1);
    const V3 psum = add(cross_abs(y1, z0), cross_abs(y0, z1));
    const double p0 = dot_abs(x0, p00), p3 = dot_abs(x1, p11);
    const double p1 = (dot_abs(x1, p00) + dot_abs(x0, psum)) / 3.0;
    const double p2 = (dot_abs(x0, p11) + dot_abs(x1, psum)) / 3.0;
    const double perm = std::max(std::max(p0, p1), std::max(p2, p3));
    err.e0 = 0x1p-49 * perm + 0x1p-900;
  }
  double big = 0.0;
  for (int i = 0; i < 4; ++i) big = std::max(big, std::fabs(f[i]));
  err.set_step(big);
}

}  // namespace tecido
