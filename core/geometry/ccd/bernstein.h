#pragma once
/// Polynomials in time over an interval, in Bernstein form, with a rigorous bound on the
/// rounding error of their computed coefficients: the certified part of core's continuous
/// collision test (ccd/ccd.h).
///
/// Over [lo, hi], p(t) = sum_i b_i B_i^n(s), s = (t - lo) / (hi - lo). Two classical facts
/// (Farouki and Rajan 1987, "On the numerical condition of polynomials in Bernstein form",
/// CAGD 4(3)) carry the whole certification:
///  - p lies between the smallest and the largest b_i on [lo, hi] (the B_i^n are nonnegative
///    and sum to 1), so all b_i > 0 proves p > 0 on the whole interval; b_0 = p(lo) and
///    b_n = p(hi) exactly;
///  - halving (de Casteljau at s = 1/2) gives the coefficients on both halves as averages of
///    averages, so every coefficient at any depth is a convex combination of those at the top.
/// Error: if every computed coefficient is within e of the true one, the computed averages
/// (fl(x + y) * 0.5, the halving exact apart from underflow) are within
/// e + eps (|x + y| / 2) + 2^-1075 of the true ones, three levels deep per halving, and every
/// true coefficient is bounded by B = max |top coefficient| + e0. So after d halvings the
/// error is at most e0 + d * step with step >= 3 (eps (B + e) + 2^-1075); step is taken as
/// 2^-49 (B + e0) + 2^-900, which also absorbs the rounding of e0 + d * step itself for the
/// depths used here (d <= 64), eps = 2^-53.
/// Restriction to [sa, sb] (blossoming, Ramshaw 1989: the coefficients on [sa, sb] are the
/// blossom values at (sa..sa), (sa..sb), ..., (sb..sb), each computed by de Casteljau-like
/// steps (1 - s) x + s y): with sa, sb multiples of 2^-52 in [0, 1], 1 - s is exact, and each
/// step adds at most eps (|(1 - s) x| + |s y|) + eps |result| <= 3 eps B (plus underflow), so a
/// restriction (three steps deep for the cubic) adds at most 9 eps B + 2^-1070: less than one
/// halving step, and the bound at depth d + 1 covers it.
#include <cmath>

namespace tecido {

/// Absolute error bound of a family of computed Bernstein coefficients: e0 at construction,
/// plus `step` per halving.
struct CcdErrorBound {
  double e0 = 0.0;
  double step = 0.0;
  /// The bound after `depth` halvings.
  double at(int depth) const { return e0 + depth * step; }
  /// Sets step from the largest |coefficient| at construction (see the file comment).
  void set_step(double max_abs_coefficient) { step = 0x1p-49 * (max_abs_coefficient + e0) + 0x1p-900; }
};

/// The largest quadratics a query needs: the denominator and four numerators (edge-edge).
inline constexpr int kCcdMaxQuadratics = 5;

/// Bernstein coefficients on one time interval of the coplanarity cubic f (ccd/coplanarity_cubic.h)
/// and of the projected quadratics q (ccd/projected_quadratics.h; q[j][k] is coefficient j
/// of quadratic k; k = 0 is the denominator).
struct CcdBernsteinSet {
  double f[4];
  double q[3][kCcdMaxQuadratics];
};

/// Halves every polynomial of p (de Casteljau at the midpoint): coefficients on the left and
/// right halves of p's interval. Averages only; see the file comment for the error.
inline void ccd_halve(const CcdBernsteinSet& p, CcdBernsteinSet& left, CcdBernsteinSet& right) {
  const double* b = p.f;
  const double m01 = (b[0] + b[1]) * 0.5, m12 = (b[1] + b[2]) * 0.5, m23 = (b[2] + b[3]) * 0.5;
  const double n0 = (m01 + m12) * 0.5, n1 = (m12 + m23) * 0.5;
  const double mid = (n0 + n1) * 0.5;
  left.f[0] = b[0];
  left.f[1] = m01;
  left.f[2] = n0;
  left.f[3] = mid;
  right.f[0] = mid;
  right.f[1] = n1;
  right.f[2] = m23;
  right.f[3] = b[3];
  for (int k = 0; k < kCcdMaxQuadratics; ++k) {
    const double a = (p.q[0][k] + p.q[1][k]) * 0.5, c = (p.q[1][k] + p.q[2][k]) * 0.5;
    const double m = (a + c) * 0.5;
    left.q[0][k] = p.q[0][k];
    left.q[1][k] = a;
    left.q[2][k] = m;
    right.q[0][k] = m;
    right.q[1][k] = c;
    right.q[2][k] = p.q[2][k];
  }
}

/// One de Casteljau step at s: (1 - s) x + s y.
inline double ccd_lerp(double x, double y, double s) { return (1.0 - s) * x + s * y; }

/// Bernstein coefficients on [sa, sb] (relative to the current interval, multiples of 2^-52
/// in [0, 1]) of the cubic b, by blossoming (see the file comment for the error).
inline void ccd_restrict_cubic(const double b[4], double sa, double sb, double out[4]) {
  const double a1[3] = {ccd_lerp(b[0], b[1], sa), ccd_lerp(b[1], b[2], sa), ccd_lerp(b[2], b[3], sa)};
  const double b1[3] = {ccd_lerp(b[0], b[1], sb), ccd_lerp(b[1], b[2], sb), ccd_lerp(b[2], b[3], sb)};
  const double aa[2] = {ccd_lerp(a1[0], a1[1], sa), ccd_lerp(a1[1], a1[2], sa)};
  const double ab[2] = {ccd_lerp(a1[0], a1[1], sb), ccd_lerp(a1[1], a1[2], sb)};
  const double bb[2] = {ccd_lerp(b1[0], b1[1], sb), ccd_lerp(b1[1], b1[2], sb)};
  out[0] = ccd_lerp(aa[0], aa[1], sa);
  out[1] = ccd_lerp(aa[0], aa[1], sb);
  out[2] = ccd_lerp(ab[0], ab[1], sb);
  out[3] = ccd_lerp(bb[0], bb[1], sb);
}

/// Bernstein coefficients on [sa, sb] of every quadratic of p (as ccd_restrict_cubic).
inline void ccd_restrict_quadratics(const double q[3][kCcdMaxQuadratics], double sa, double sb,
                                    double out[3][kCcdMaxQuadratics]) {
  for (int k = 0; k < kCcdMaxQuadratics; ++k) {
    const double a0 = ccd_lerp(q[0][k], q[1][k], sa), a1 = ccd_lerp(q[1][k], q[2][k], sa);
    const double b0 = ccd_lerp(q[0][k], q[1][k], sb), b1 = ccd_lerp(q[1][k], q[2][k], sb);
    out[0][k] = ccd_lerp(a0, a1, sa);
    out[1][k] = ccd_lerp(a0, a1, sb);
    out[2][k] = ccd_lerp(b0, b1, sb);
  }
}

/// +1 when every one of the n coefficients b[0], b[stride], ... exceeds e (the polynomial is
/// certainly positive on the interval), -1 when every one is below -e, 0 otherwise.
inline int ccd_certified_sign(const double* b, int n, int stride, double e) {
  double lo = b[0], hi = b[0];
  for (int i = 1; i < n; ++i) {
    const double v = b[i * stride];
    lo = v < lo ? v : lo;
    hi = v > hi ? v : hi;
  }
  if (lo > e) return 1;
  if (hi < -e) return -1;
  return 0;
}

}  // namespace tecido
