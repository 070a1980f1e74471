#pragma once
/// Exact-sign orientation predicates (Shewchuk 1997, "Adaptive Precision Floating-Point
/// Arithmetic and Fast Robust Geometric Predicates", Discrete Comput. Geom. 18:305-363).
///
/// Each predicate runs in stages, each one only when the previous cannot decide:
///  1. a floating-point filter: Shewchuk's static error bound "A" (orient2d: (3+16e)e,
///     orient3d: (7+56e)e times the permanent, e = 2^-53), plus a tiny absolute term that
///     covers underflow, which Shewchuk's bound ignores. Overflow (inf/NaN) fails the filter.
///     Inline: this is the hot path.
///  2. Shewchuk's adaptive stages B and C (the exact determinant of the rounded differences,
///     then first-order corrections from their round-off tails, each with his error bound),
///     on inputs whose nonzero coordinates lie in [2^-250, 2^250], where his no-underflow,
///     no-overflow assumptions provably hold.
///  3. exact expansion arithmetic (two_sum, two_product via std::fma, scale and sum of
///     expansions) on the coordinate differences, after scaling each coordinate axis by a
///     power of two so that nothing can overflow. Expansion arithmetic is exact barring
///     overflow and underflow; this stage is used only when no partial product can underflow,
///     which is checked from the exponents: with s_c = log2(max |coord| / min nonzero |coord|)
///     on axis c, orient3d needs sum_c s_c <= ~1920 bits and orient2d s_x + s_y <= ~1960 bits
///     (e.g. every input whose nonzero magnitudes lie within [1e-90, 1e100]).
///  4. otherwise, a fixed-size big-integer evaluation of the determinant (every double is an
///     integer times a power of two), exact for every finite input.
/// So the sign returned is exact for EVERY finite double input. NaN/Inf inputs are not
/// supported (the result is unspecified). Requires IEEE-754 doubles with round-to-nearest and
/// no -ffast-math.
#include "core/geometry/types.h"

#include <cmath>
#include <cstdint>

namespace tecido {

/// Sign of det[a-d; b-d; c-d] (Shewchuk's orient3d): +1 when d lies below the plane through
/// a, b, c, "below" meaning a, b, c appear counter-clockwise seen from above; equivalently
/// +1 when (d - a) . ((b - a) x (c - a)) < 0, i.e. d is on the side opposite the right-hand
/// normal of a->b->c. 0 when the four points are coplanar (or a, b, c collinear). Exact for
/// any finite input (see the file comment). Method: Shewchuk 1997, filtered, exact fallback.
inline int orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// Sign of det[a-c; b-c] = (ax-cx)(by-cy) - (ay-cy)(bx-cx) (Shewchuk's orient2d): +1 when
/// a, b, c are counter-clockwise (c left of the directed line a->b), -1 clockwise, 0 when
/// collinear. Exact for any finite input. Method: Shewchuk 1997, filtered, exact fallback.
inline int orient2d_sign(double ax, double ay, double bx, double by, double cx, double cy);

/// Number of calls, on the calling thread, that failed the floating-point filter and took
/// the exact path (stages 2 to 4). A diagnostic for benchmarks; it never resets by itself.
std::uint64_t orient_exact_path_count();

namespace detail {

/// orient3d_sign without the filter (stages 2 to 4 above). Counts towards
/// orient_exact_path_count().
int orient3d_sign_exact(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// orient2d_sign without the filter (stages 2 to 4).
int orient2d_sign_exact(double ax, double ay, double bx, double by, double cx, double cy);

/// Stage 4 alone: the 4x4 determinant [x y z 1] summed exactly in a big integer. Slow;
/// exposed so tests can check the other exact stages against an independent method.
int orient3d_sign_bigint(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);
/// Stage 4 alone for orient2d (3x3 determinant [x y 1]).
int orient2d_sign_bigint(double ax, double ay, double bx, double by, double cx, double cy);

inline constexpr double kUnitRoundoff = 0x1p-53;
/// Shewchuk 1997 (predicates.c): ccwerrboundA and o3derrboundA.
inline constexpr double kOrient2dErrBoundA = (3.0 + 16.0 * kUnitRoundoff) * kUnitRoundoff;
inline constexpr double kOrient3dErrBoundA = (7.0 + 56.0 * kUnitRoundoff) * kUnitRoundoff;
/// Shewchuk's bounds assume no underflow. A product that underflows is off by at most 2^-1075
/// in absolute terms; orient2d adds this pad to its bound, orient3d, which multiplies its
/// first-level products by a z difference, adds it times (sum |dz| + 2). 2^-1000 is far more
/// than those errors need and far below any determinant of non-degenerate inputs, so it costs
/// no filter efficiency; it is a normal number on purpose: a subnormal pad (or a subnormal
/// product with one) would make every filter evaluation take the CPU's slow subnormal path.
inline constexpr double kUnderflowPad = 0x1p-1000;

}  // namespace detail

// The filters are inline (they are the hot path); the exact stages are out of line.

inline int orient2d_sign(double ax, double ay, double bx, double by, double cx, double cy) {
  // Shewchuk's orient2d filter. The signs of the two products are exact (rounding keeps
  // signs; a product that underflows to 0 is smaller than any nonzero product of the other
  // kind), so when they differ the sign of det is known without a bound.
  const double detleft = (ax - cx) * (by - cy);
  const double detright = (ay - cy) * (bx - cx);
  const double det = detleft - detright;
  double detsum;
  if (detleft > 0.0) {
    if (detright <= 0.0) return 1;
    detsum = detleft + detright;
  } else if (detleft < 0.0) {
    if (detright >= 0.0) return -1;
    detsum = -detleft - detright;
  } else {
    if (detright > 0.0) return -1;
    if (detright < 0.0) return 1;
    return detail::orient2d_sign_exact(ax, ay, bx, by, cx, cy);  // both 0: maybe underflow
  }
  const double errbound = detail::kOrient2dErrBoundA * detsum + detail::kUnderflowPad;
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  return detail::orient2d_sign_exact(ax, ay, bx, by, cx, cy);
}

inline int orient3d_sign(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  // Shewchuk's orient3d filter (error bound A), with the absolute pad for underflow.
  const double adx = a[0] - d[0], bdx = b[0] - d[0], cdx = c[0] - d[0];
  const double ady = a[1] - d[1], bdy = b[1] - d[1], cdy = c[1] - d[1];
  const double adz = a[2] - d[2], bdz = b[2] - d[2], cdz = c[2] - d[2];
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  const double det = adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady);
  const double aadz = std::fabs(adz), abdz = std::fabs(bdz), acdz = std::fabs(cdz);
  const double permanent = (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * aadz +
                           (std::fabs(cdxady) + std::fabs(adxcdy)) * abdz +
                           (std::fabs(adxbdy) + std::fabs(bdxady)) * acdz;
  const double errbound = detail::kOrient3dErrBoundA * permanent +
                          (aadz + abdz + acdz + 2.0) * detail::kUnderflowPad;
  // Overflow makes det or errbound inf/NaN: both comparisons fail and the exact path runs.
  if (det > errbound) return 1;
  if (-det > errbound) return -1;
  // A column of exact zeros (the four points share a coordinate) makes the determinant 0.
  if ((adx == 0 && bdx == 0 && cdx == 0) || (ady == 0 && bdy == 0 && cdy == 0) || (adz == 0 && bdz == 0 && cdz == 0)) return 0;
  return detail::orient3d_sign_exact(a, b, c, d);
}

}  // namespace tecido
