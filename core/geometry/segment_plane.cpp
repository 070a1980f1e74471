// Segment versus bounded plane with an exact decision: a floating-point filter, then exact
// dyadic arithmetic (see segment_plane.h for the polynomials whose signs decide).
//
// The filter's error bound. Every sign the test needs is the sign of a polynomial V in the
// stored doubles (P, n, f, hx, hy, p1, p2), evaluated in floating point along a fixed
// expression tree. With u = 2^-53 and Higham's model (Accuracy and Stability of Numerical
// Algorithms, 2nd ed., 2002, section 2.2; round to nearest): fl(x op y) = (x op y)(1 + d),
// |d| <= u, when nothing underflows or overflows. Expanding V into monomials (taking each
// difference p_k - P_k as one factor), each monomial is computed times a product of at most
// k factors (1 + d), k = the number of roundings on its path, so
//   |V_computed - V| <= gamma_k Perm,  gamma_k = k u / (1 - k u),
// where Perm is the same expression with every monomial replaced by its absolute value (the
// "permanent", Shewchuk 1997). The permanent is computed in floating point from the same
// rounded intermediates; each of its roundings and each rounded difference contribute a factor
// (1 + u) at most, so Perm <= (1 + u)^m Perm_computed with m <= 16. Depths here (roundings):
//   d = p - P: 1;  s = n.d, a = f.d: 4;  r_k = n_i f_j - n_j f_i: 2;  b = r.d: 6;
//   X = hx sigma (s1 - s2) - |s1 a2 - s2 a1|: 11;  Y (the same with b, hy): 13;
//   in the plane: a_i -/+ hx: 5, b_i -/+ hy: 7, a2 - a1: 5, b2 - b1: 7, a1 b2 - a2 b1: 12,
//   Z = hx |b2 - b1| + hy |a2 - a1| - |a1 b2 - a2 b1|: 13.
// (The signs of s1 and s2 come first, from plane_side_sign's own bound, plane_side.h, which
// also covers underflow, so that a segment on one side is rejected before anything else.)
// So k <= 13 and gamma_13 (1 + u)^16 < 14u: kErr = 16u = 2^-49 times the computed permanent
// bounds every error, and, being a power of two, scaling by it is exact (see below), so the
// bound itself is not rounded down. Absolute values are not polynomials; where V holds |A|, the
// computed |A| is sign(A_computed) A_computed, so V_computed is the computed value of the
// polynomial V' with that fixed sign; V >= 0 needs both signs' V' >= 0, and rounding is
// monotonic, so V_computed > err implies both V' > 0 (the other one is computed larger), and
// V_computed < -err implies V' < 0 hence V <= V' < 0. The same holds for the filter's |s1 - s2|,
// taken as sigma (s1 - s2) with sigma the exactly known sign, and for Z, whose |a2 - a1|,
// |b2 - b1| and |a1 b2 - a2 b1| are first given exact signs by the filter.
//
// No underflow, no overflow: the filter runs only when every input is 0 or of magnitude in
// [2^-150, 2^150] ("tame"). Each input is then a multiple of 2^-202, so is each difference d;
// products and sums of multiples of 2^-a and 2^-b are multiples of 2^-(a+b) and 2^-min(a,b),
// and rounding to nearest keeps that (the result is a multiple of the larger of its ulp and the
// granularity). So r is a multiple of 2^-404, s and a of 2^-404, b of 2^-606, every degree-5
// product and permanent of 2^-1010, and 2^-49 times it of 2^-1059: every nonzero intermediate is
// at least 2^-1059, so none is subnormal-rounded, and a permanent that is 0 means the value is
// exactly 0. At the top, inputs below 2^150 keep every intermediate below 2^770. Inputs outside
// that range (or NaN/inf) go straight to the exact path.
#include "core/geometry/segment_plane.h"

#include "core/geometry/exact_dyadic.h"
#include "core/geometry/plane_side.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#if defined(__FAST_MATH__)
#error "segment_plane.cpp's filter relies on IEEE-754 rounding: do not build it with -ffast-math"
#endif

namespace tecido {

namespace {

thread_local std::uint64_t g_exact_path_calls = 0;

constexpr double kErr = 0x1p-49;  // 16u, see the file comment
constexpr int kUndecided = 2;

/// The sign of v known to within err of the exact value: +1 or -1 when |v| > err, 0 when err is
/// 0 (the permanent is 0, so the value is exactly 0, in the tame range), else kUndecided.
inline int filtered_sign(double v, double err) {
  if (v > err) return 1;
  if (v < -err) return -1;
  return err == 0.0 ? 0 : kUndecided;
}

/// 1 unless v is 0 or of magnitude in [2^-150, 2^150] (NaN and infinities included), branch-free:
/// the bit patterns of non-negative doubles are ordered like their values.
inline unsigned untame(double v) {
  constexpr std::uint64_t kLo = 0x3690000000000000ULL;  // 2^-150
  constexpr std::uint64_t kHi = 0x4950000000000000ULL;  // 2^150
  std::uint64_t b;
  std::memcpy(&b, &v, sizeof b);
  b &= 0x7fffffffffffffffULL;
  return static_cast<unsigned>(b - kLo > kHi - kLo) & static_cast<unsigned>(b != 0);
}

inline unsigned untame(const Vec3& v) { return untame(v.x()) | untame(v.y()) | untame(v.z()); }

/// Whether every input is tame (see the file comment), the filter's domain.
inline bool tame_inputs(const BoundedPlane& pl, const Vec3& p1, const Vec3& p2) {
  return (untame(pl.position) | untame(pl.normal) | untame(pl.forward) | untame(p1) | untame(p2) |
          untame(pl.half_extents.x()) | untame(pl.half_extents.y())) == 0;
}

/// An end point in the plane's frame, in floating point, with the permanents of s, a and b.
/// side_of fills d, s and ps (all the same-side rejection needs); forward_of and right_of the rest.
struct Frame {
  double d[3], ad[3];
  double s, a, b, ps, pa, pb;
};

Frame side_of(const BoundedPlane& pl, const Vec3& p) {
  const Vec3& n = pl.normal;
  Frame e;
  for (int k = 0; k < 3; ++k) {
    e.d[k] = p[k] - pl.position[k];
    e.ad[k] = std::fabs(e.d[k]);
  }
  e.s = (n.x() * e.d[0] + n.y() * e.d[1]) + n.z() * e.d[2];
  e.ps = (std::fabs(n.x()) * e.ad[0] + std::fabs(n.y()) * e.ad[1]) + std::fabs(n.z()) * e.ad[2];
  return e;
}

/// The exact sign of s from its floating-point value, or kUndecided. The bound of plane_side_sign
/// (plane_side.h), valid for every input, tame or not: s is computed the same way.
int side_sign(const BoundedPlane& pl, const Frame& e) {
  const double err = detail::kSideErrBound * e.ps + detail::kSideUnderflowPad;
  if (e.s > err) return 1;
  if (e.s < -err) return -1;
  const Vec3& n = pl.normal;
  if ((n.x() == 0.0 || e.d[0] == 0.0) && (n.y() == 0.0 || e.d[1] == 0.0) && (n.z() == 0.0 || e.d[2] == 0.0)) return 0;
  return kUndecided;
}

/// a = f.d with its permanent.
void forward_of(const Vec3& f, Frame& e) {
  e.a = (f.x() * e.d[0] + f.y() * e.d[1]) + f.z() * e.d[2];
  e.pa = (std::fabs(f.x()) * e.ad[0] + std::fabs(f.y()) * e.ad[1]) + std::fabs(f.z()) * e.ad[2];
}

/// b = r.d with its permanent, for both end points; r = n x f rounded, rp its permanent.
void right_of(const BoundedPlane& pl, Frame& e1, Frame& e2) {
  const Vec3& n = pl.normal;
  const Vec3& f = pl.forward;
  const Vec3 r(n.y() * f.z() - n.z() * f.y(), n.z() * f.x() - n.x() * f.z(), n.x() * f.y() - n.y() * f.x());
  const Vec3 rp(std::fabs(n.y() * f.z()) + std::fabs(n.z() * f.y()), std::fabs(n.z() * f.x()) + std::fabs(n.x() * f.z()),
                std::fabs(n.x() * f.y()) + std::fabs(n.y() * f.x()));
  for (Frame* e : {&e1, &e2}) {
    e->b = (r.x() * e->d[0] + r.y() * e->d[1]) + r.z() * e->d[2];
    e->pb = (rp.x() * e->ad[0] + rp.y() * e->ad[1]) + rp.z() * e->ad[2];
  }
}

/// Whether the crossing point's coordinate v (a with h = hx, or b with h = hy) lies in [-h, h]:
/// the sign of h |s1 - s2| - |s1 v2 - s2 v1|, with sigma = sign(s1 - s2) known exactly;
/// +1, -1, 0 or kUndecided. pv1, pv2 are the permanents of v1, v2.
int crossing_within(const Frame& e1, const Frame& e2, double v1, double pv1, double v2, double pv2, int sigma,
                    double h) {
  const double dabs = sigma * (e1.s - e2.s);
  const double x = h * dabs - std::fabs(e1.s * v2 - e2.s * v1);
  return filtered_sign(x, kErr * (h * (e1.ps + e2.ps) + (e1.ps * pv2 + e2.ps * pv1)));
}

/// Whether the interval of v1, v2 (permanents p1, p2) lies strictly beyond h on one side:
/// 1, 0 or kUndecided.
int beyond(double v1, double p1, double v2, double p2, double h) {
  for (const double side : {1.0, -1.0}) {  // v_i > h, then v_i < -h
    const int g1 = filtered_sign(side * v1 - h, kErr * (p1 + h));
    const int g2 = filtered_sign(side * v2 - h, kErr * (p2 + h));
    if (g1 == 1 && g2 == 1) return 1;
    if (g1 == kUndecided && g2 != 0 && g2 != -1) return kUndecided;
    if (g2 == kUndecided && g1 != 0 && g1 != -1) return kUndecided;
  }
  return 0;
}

/// The segment lying in the plane against the closed rectangle, by separating axes: the
/// rectangle's axes (the segment's a and b ranges overlap [-hx, hx] and [-hy, hy]) and the
/// segment's normal (Z = hx |b2 - b1| + hy |a2 - a1| - |a1 b2 - a2 b1| >= 0). 1, 0 or kUndecided.
int in_plane_inside(const Frame& e1, const Frame& e2, double hx, double hy) {
  const int ba = beyond(e1.a, e1.pa, e2.a, e2.pa, hx), bb = beyond(e1.b, e1.pb, e2.b, e2.pb, hy);
  if (ba == 1 || bb == 1) return 0;
  if (ba == kUndecided || bb == kUndecided) return kUndecided;
  const double ea = e2.a - e1.a, eb = e2.b - e1.b, l = e1.a * e2.b - e2.a * e1.b;
  const double pea = e1.pa + e2.pa, peb = e1.pb + e2.pb, pl = e1.pa * e2.pb + e2.pa * e1.pb;
  const int ta = filtered_sign(ea, kErr * pea), tb = filtered_sign(eb, kErr * peb), tl = filtered_sign(l, kErr * pl);
  if (ta == kUndecided || tb == kUndecided || tl == kUndecided) return kUndecided;
  const double z = (hx * (tb * eb) + hy * (ta * ea)) - tl * l;
  const int sz = filtered_sign(z, kErr * ((hx * peb + hy * pea) + pl));
  return sz == kUndecided ? kUndecided : (sz >= 0 ? 1 : 0);
}

/// The first t in [0, 1] at which (a, b)(t) enters the box |a| <= hx, |b| <= hy, given that the
/// segment meets it (Liang-Barsky's entering parameters, without its rejection tests, which the
/// exact decision has already made). Clamped to [0, 1]; 0 when rounding gives no number.
double entry_fraction(double a1, double a2, double b1, double b2, double hx, double hy) {
  double t = 0.0;
  auto enter = [&t](double v1, double v2, double h) {
    const double dv = v2 - v1;
    if (v1 > h && dv < 0.0) t = std::max(t, (v1 - h) / -dv);
    if (v1 < -h && dv > 0.0) t = std::max(t, (-h - v1) / dv);
  };
  enter(a1, a2, hx);
  enter(b1, b2, hy);
  return t >= 0.0 && t <= 1.0 ? t : (t > 1.0 ? 1.0 : 0.0);
}

/// s1 / (s1 - s2) for s1, s2 of opposite strict signs: |s1| / (|s1| + |s2|), in [0, 1].
double crossing_fraction(double s1, double s2) {
  const double a1 = std::fabs(s1), a2 = std::fabs(s2);
  return a1 / (a1 + a2);
}

/// The same from exact values, whatever their magnitudes.
double crossing_fraction(const Dyadic& s1, const Dyadic& s2) {
  long e1 = 0, e2 = 0;
  const double m1 = std::fabs(s1.approx_mantissa(&e1)), m2 = std::fabs(s2.approx_mantissa(&e2));
  const long e = std::max(e1, e2);
  const double v1 = std::ldexp(m1, static_cast<int>(std::max(e1 - e, -2000L)));
  const double v2 = std::ldexp(m2, static_cast<int>(std::max(e2 - e, -2000L)));
  return v1 / (v1 + v2);
}

double to_double(const Dyadic& x) {
  long e = 0;
  const double m = x.approx_mantissa(&e);
  return std::ldexp(m, static_cast<int>(std::clamp(e, -4000L, 4000L)));
}

/// An end point in the plane's frame, exactly: d = p - P, and s, a, b once computed.
struct ExactFrame {
  Dyadic d[3], s, a, b;
};

Dyadic dot(const Dyadic (&v)[3], const Dyadic (&d)[3]) { return v[0] * d[0] + v[1] * d[1] + v[2] * d[2]; }

Dyadic dot(const Vec3& v, const Dyadic (&d)[3]) { return dot({Dyadic(v.x()), Dyadic(v.y()), Dyadic(v.z())}, d); }

/// e.d and e.s for the end point p.
void exact_side(const BoundedPlane& pl, const Vec3& p, ExactFrame& e) {
  for (int k = 0; k < 3; ++k) e.d[k] = Dyadic(p[k]) - Dyadic(pl.position[k]);
  e.s = dot(pl.normal, e.d);
}

/// e1.b and e2.b, with r = n x f exactly.
void exact_right(const BoundedPlane& pl, ExactFrame& e1, ExactFrame& e2) {
  const Dyadic n[3] = {Dyadic(pl.normal.x()), Dyadic(pl.normal.y()), Dyadic(pl.normal.z())};
  const Dyadic f[3] = {Dyadic(pl.forward.x()), Dyadic(pl.forward.y()), Dyadic(pl.forward.z())};
  const Dyadic r[3] = {n[1] * f[2] - n[2] * f[1], n[2] * f[0] - n[0] * f[2], n[0] * f[1] - n[1] * f[0]};
  e1.b = dot(r, e1.d);
  e2.b = dot(r, e2.d);
}

/// in_plane_inside, exactly.
bool in_plane_inside_exact(const ExactFrame& e1, const ExactFrame& e2, const Dyadic& hx, const Dyadic& hy) {
  auto beyond = [](const Dyadic& v1, const Dyadic& v2, const Dyadic& h) {
    return (compare(v1, h) > 0 && compare(v2, h) > 0) || (compare(v1, -h) < 0 && compare(v2, -h) < 0);
  };
  if (beyond(e1.a, e2.a, hx) || beyond(e1.b, e2.b, hy)) return false;
  const Dyadic ea = e2.a - e1.a, eb = e2.b - e1.b, l = e1.a * e2.b - e2.a * e1.b;
  return (hx * eb.abs() + hy * ea.abs() - l.abs()).sign() >= 0;
}

bool finite_inputs(const BoundedPlane& pl, const Vec3& p1, const Vec3& p2) {
  return pl.position.allFinite() && pl.normal.allFinite() && pl.forward.allFinite() && p1.allFinite() &&
         p2.allFinite() && std::isfinite(pl.half_extents.x()) && std::isfinite(pl.half_extents.y());
}

}  // namespace

std::uint64_t segment_plane_exact_path_count() { return g_exact_path_calls; }

namespace detail {

SegmentPlaneHit segment_plane_exact(const BoundedPlane& pl, const Vec3& p1, const Vec3& p2) {
  ++g_exact_path_calls;
  if (!finite_inputs(pl, p1, p2) || !(pl.half_extents.x() >= 0.0 && pl.half_extents.y() >= 0.0)) return {};
  ExactFrame e1, e2;
  exact_side(pl, p1, e1);
  exact_side(pl, p2, e2);
  const int sg1 = e1.s.sign(), sg2 = e2.s.sign();
  if (sg1 * sg2 > 0) return {};
  e1.a = dot(pl.forward, e1.d);
  e2.a = dot(pl.forward, e2.d);
  const Dyadic hx(pl.half_extents.x()), hy(pl.half_extents.y());
  if (sg1 == 0 && sg2 == 0) {
    exact_right(pl, e1, e2);
    if (!in_plane_inside_exact(e1, e2, hx, hy)) return {};
    return {true, entry_fraction(to_double(e1.a), to_double(e2.a), to_double(e1.b), to_double(e2.b),
                                 pl.half_extents.x(), pl.half_extents.y())};
  }
  const int sigma = sg1 != 0 ? sg1 : -sg2;
  const Dyadic dabs = (e1.s - e2.s).times_sign(sigma);
  if ((hx * dabs - (e1.s * e2.a - e2.s * e1.a).abs()).sign() < 0) return {};
  exact_right(pl, e1, e2);
  if ((hy * dabs - (e1.s * e2.b - e2.s * e1.b).abs()).sign() < 0) return {};
  return {true, sg1 == 0 ? 0.0 : (sg2 == 0 ? 1.0 : crossing_fraction(e1.s, e2.s))};
}

}  // namespace detail

SegmentPlaneHit segment_plane(const BoundedPlane& pl, const Vec3& p1, const Vec3& p2) {
  const double hx = pl.half_extents.x(), hy = pl.half_extents.y();
  Frame e1 = side_of(pl, p1), e2 = side_of(pl, p2);
  const int sg1 = side_sign(pl, e1), sg2 = side_sign(pl, e2);
  if (sg1 * sg2 == 1) return {};  // both strictly on one side: no crossing (the common case)
  if (sg1 == kUndecided || sg2 == kUndecided || !tame_inputs(pl, p1, p2)) return detail::segment_plane_exact(pl, p1, p2);
  if (hx < 0.0 || hy < 0.0) return {};
  forward_of(pl.forward, e1);
  forward_of(pl.forward, e2);
  if (sg1 == 0 && sg2 == 0) {  // the segment lies in the plane
    right_of(pl, e1, e2);
    const int in = in_plane_inside(e1, e2, hx, hy);
    if (in == kUndecided) return detail::segment_plane_exact(pl, p1, p2);
    if (in == 0) return {};
    return {true, entry_fraction(e1.a, e2.a, e1.b, e2.b, hx, hy)};
  }
  // Different sides, or exactly one end point on the plane: one crossing point; b only when a
  // is not already outside.
  const int sigma = sg1 != 0 ? sg1 : -sg2;
  const int sx = crossing_within(e1, e2, e1.a, e1.pa, e2.a, e2.pa, sigma, hx);
  if (sx == -1) return {};
  right_of(pl, e1, e2);
  const int sy = crossing_within(e1, e2, e1.b, e1.pb, e2.b, e2.pb, sigma, hy);
  if (sy == -1) return {};
  if (sx == kUndecided || sy == kUndecided) return detail::segment_plane_exact(pl, p1, p2);
  return {true, sg1 == 0 ? 0.0 : (sg2 == 0 ? 1.0 : crossing_fraction(e1.s, e2.s))};
}

}  // namespace tecido
