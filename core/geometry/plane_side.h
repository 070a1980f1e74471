#pragma once
/// The exact side of a point with respect to a plane: the sign of normal . (p - position),
/// evaluated on the stored doubles as exact numbers (the side test of the seed's
/// DETECTACOLISÃO, seed section 3.1.1, made exact). The simulation's side bookkeeping and
/// segment_plane's crossing test use the same exact sign, so they never disagree.
#include "core/geometry/bounded_plane.h"

#include <cmath>

namespace tecido {

/// +1 when p lies strictly on the normal's side of the plane, -1 strictly on the other side,
/// 0 exactly on it; exact for every finite input. Method: a floating-point filter with a
/// rigorous error bound (below); when it cannot decide, Shewchuk's expansion arithmetic
/// (core/geometry/expansion_arithmetic.h) for inputs within [2^-450, 2^450] in magnitude, exact
/// dyadic arithmetic (core/geometry/exact_dyadic.h) beyond. NaN or infinite inputs: unspecified
/// result, never throws.
inline int plane_side_sign(const BoundedPlane& plane, const Vec3& p);

namespace detail {

/// The exact stages alone (no filter): expansions, or Dyadic arithmetic for extreme inputs.
/// Non-finite input: the sign of the floating-point value (0 for NaN).
int plane_side_sign_exact(const BoundedPlane& plane, const Vec3& p);

/// Error bound of the filter, relative to the permanent sum |n_k| |d_k|. With u = 2^-53 and
/// Higham's model of rounding (Accuracy and Stability of Numerical Algorithms, 2nd ed., 2002,
/// section 2.2: fl(x op y) = (x op y)(1 + d), |d| <= u, plus an absolute error of at most
/// 2^-1075 when a product underflows; sums and differences that underflow are exact), every
/// monomial n_k (p_k - P_k) of s is computed through at most 4 roundings (the difference, the
/// product, two sums), so |s_computed - s| <= gamma_4 sum |n_k d_k| + 3 2^-1075 (1 + u)^2,
/// gamma_4 = 4u / (1 - 4u). The permanent computed in floating point (3 more roundings, and
/// |d_k| <= (1 + u) |d_k computed|) is at least sum |n_k d_k| / (1 + u)^4 less the same
/// underflow terms, so 8u times it plus kSideUnderflowPad bounds the error with room to spare
/// for the rounding of the bound itself (8u is a power of two: scaling by it is exact).
inline constexpr double kSideErrBound = 0x1p-50;  // 8u
/// Covers the underflow terms above (each at most 2^-1075) many times over; a normal number,
/// so the filter never works on subnormals.
inline constexpr double kSideUnderflowPad = 0x1p-1000;

}  // namespace detail

inline int plane_side_sign(const BoundedPlane& plane, const Vec3& p) {
  const Vec3& n = plane.normal;
  const double dx = p.x() - plane.position.x(), dy = p.y() - plane.position.y(), dz = p.z() - plane.position.z();
  const double tx = n.x() * dx, ty = n.y() * dy, tz = n.z() * dz;
  const double s = (tx + ty) + tz;
  const double err = detail::kSideErrBound * ((std::fabs(tx) + std::fabs(ty)) + std::fabs(tz)) + detail::kSideUnderflowPad;
  // Overflow makes s or err infinite or NaN: both comparisons fail and the exact stage runs.
  if (s > err) return 1;
  if (s < -err) return -1;
  // Every monomial exactly zero (a difference is 0 only when the coordinates are equal):
  // the common case of a point on an axis-aligned plane.
  if ((n.x() == 0.0 || dx == 0.0) && (n.y() == 0.0 || dy == 0.0) && (n.z() == 0.0 || dz == 0.0)) return 0;
  return detail::plane_side_sign_exact(plane, p);
}

}  // namespace tecido
