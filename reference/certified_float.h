#pragma once
/// Certified floating-point arithmetic for the exact referee's filters (exact_ccd_filter.cpp,
/// exact_ccd_feature_contact.cpp): every number is a pair (v, e), the exact quantity lies in
/// [v - e, v + e]. Error bounds follow the standard model of IEEE round-to-nearest,
/// |fl(x op y) - x op y| <= u |fl(x op y)| + eta (u = 2^-53, eta = 2^-1074 for results in the
/// subnormal range; additions never underflow), and the bound's own rounding is covered by a
/// factor (1 + 8u) and an absolute 4 eta (see up()). An overflow makes v or e infinite and a NaN
/// fails every comparison: both make a sign uncertain, never wrong.
#include "core/geometry/types.h"

#include <cmath>

namespace tecido::reference::certified {

constexpr double kU = 0x1p-53;
constexpr double kEta = 0x1p-1074;

/// A bound computed in floating point, enlarged so that it bounds the exact bound: the few
/// roundings of its computation (relative u each, fewer than 7) and underflows (eta each).
inline double up(double x) { return x * (1 + 8 * kU) + 4 * kEta; }

struct Fe {
  double v = 0, e = 0;
};
inline Fe exact(double x) { return {x, 0}; }
inline Fe operator+(Fe a, Fe b) {
  const double v = a.v + b.v;
  return {v, up(a.e + b.e + kU * std::fabs(v))};
}
inline Fe operator-(Fe a, Fe b) {
  const double v = a.v - b.v;
  return {v, up(a.e + b.e + kU * std::fabs(v))};
}
inline Fe operator*(Fe a, Fe b) {
  const double v = a.v * b.v;
  return {v, up(std::fabs(a.v) * b.e + std::fabs(b.v) * a.e + a.e * b.e + kU * std::fabs(v) + kEta)};
}
inline Fe third(Fe a) {
  const double v = a.v / 3;
  return {v, up(a.e / 3 + kU * std::fabs(v) + kEta)};
}
/// +1 or -1 when the sign is proven, 0 when it is not (including every exact zero).
inline int sign(Fe a) { return a.v > a.e ? 1 : (-a.v > a.e ? -1 : 0); }

struct FeV {
  Fe x, y, z;
};
inline FeV operator-(const FeV& a, const FeV& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline FeV cross(const FeV& a, const FeV& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline Fe dot(const FeV& a, const FeV& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline Fe det(const FeV& a, const FeV& b, const FeV& c) { return dot(cross(a, b), c); }
inline FeV exact(const Vec3& p) { return {exact(p.x()), exact(p.y()), exact(p.z())}; }

/// The point x0 + t (x1 - x0) at the time t (an interval or a double); the given points
/// themselves, unrounded, at t = 0 and t = 1.
inline FeV position_at(const Vec3& x0, const Vec3& x1, Fe t) {
  const FeV p0 = exact(x0);
  if (t.e == 0 && t.v == 0) return p0;
  if (t.e == 0 && t.v == 1) return exact(x1);
  const FeV d = exact(x1) - p0;
  return {p0.x + t * d.x, p0.y + t * d.y, p0.z + t * d.z};
}

}  // namespace tecido::reference::certified
