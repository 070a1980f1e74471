#pragma once
/// Expansion arithmetic (Shewchuk 1997, "Adaptive Precision Floating-Point Arithmetic and Fast
/// Robust Geometric Predicates", Discrete Comput. Geom. 18:305-363, sections 2 and 3): a real
/// number held exactly as an expansion, an array of nonoverlapping doubles in increasing
/// magnitude whose exact sum is the value, built with error-free transformations (Knuth's
/// two-sum, an FMA two-product). Exact barring overflow, and underflow of a product's low part:
/// callers check their inputs' range first (orient_predicates.cpp, plane_side.cpp). Requires
/// IEEE-754 doubles with round-to-nearest-even and no -ffast-math. Shared by the orientation
/// predicates and the plane-side sign.
#include <algorithm>
#include <cmath>

namespace tecido::expansion {

inline int sign_of(double x) { return (x > 0.0) - (x < 0.0); }

// ---------------------------------------------------------------------------------------
// Error-free transformations (Shewchuk 1997, section 2; Knuth's two-sum; FMA two-product).
inline void two_sum(double a, double b, double& x, double& y) {
  x = a + b;
  const double bv = x - a;
  const double av = x - bv;
  y = (a - av) + (b - bv);
}

inline void two_diff(double a, double b, double& x, double& y) {
  x = a - b;
  const double bv = a - x;
  const double av = x + bv;
  y = (a - av) + (bv - b);
}

inline void two_product(double a, double b, double& x, double& y) {
  x = a * b;
  y = std::fma(a, b, -x);  // exact low part barring underflow
}

// Expansions: arrays of nonoverlapping doubles in increasing magnitude whose exact sum is the
// value; zero components are eliminated, so the value zero has length 0 and the sign of a
// nonempty expansion is the sign of its last (largest) component.

/// a - b as an expansion of length <= 2.
inline int diff_expansion(double a, double b, double* h) {
  double x, y;
  two_diff(a, b, x, y);
  int n = 0;
  if (y != 0.0) h[n++] = y;
  if (x != 0.0) h[n++] = x;
  return n;
}

/// h = b * e (Shewchuk's scale_expansion_zeroelim); h needs room for 2 * elen.
inline int scale_expansion(int elen, const double* e, double b, double* h) {
  if (elen == 0 || b == 0.0) return 0;
  int n = 0;
  double q, hh;
  two_product(e[0], b, q, hh);
  if (hh != 0.0) h[n++] = hh;
  for (int i = 1; i < elen; ++i) {
    double p1, p0, s;
    two_product(e[i], b, p1, p0);
    two_sum(q, p0, s, hh);
    if (hh != 0.0) h[n++] = hh;
    two_sum(p1, s, q, hh);  // Shewchuk uses fast_two_sum here; two_sum is exact regardless
    if (hh != 0.0) h[n++] = hh;
  }
  if (q != 0.0) h[n++] = q;
  return n;
}

/// h = e + f (Shewchuk's fast_expansion_sum_zeroelim: merge by magnitude, then a chain of
/// two_sums); h needs room for elen + flen.
inline int sum_expansion(int elen, const double* e, int flen, const double* f, double* h) {
  if (elen == 0) {
    std::copy(f, f + flen, h);
    return flen;
  }
  if (flen == 0) {
    std::copy(e, e + elen, h);
    return elen;
  }
  int i = 0, j = 0, n = 0;
  auto next = [&]() -> double {
    if (j >= flen || (i < elen && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  double q = next();
  while (i < elen || j < flen) {
    const double g = next();
    double qn, hh;
    two_sum(q, g, qn, hh);
    if (hh != 0.0) h[n++] = hh;
    q = qn;
  }
  if (q != 0.0) h[n++] = q;
  return n;
}

/// h = e * f for a short f (length <= 2); h needs room for 2 * elen * flen.
inline int mul_expansion(int elen, const double* e, int flen, const double* f, double* h) {
  double t0[64], t1[64];
  if (flen == 0) return 0;
  if (flen == 1) return scale_expansion(elen, e, f[0], h);
  const int n0 = scale_expansion(elen, e, f[0], t0);
  const int n1 = scale_expansion(elen, e, f[1], t1);
  return sum_expansion(n0, t0, n1, t1, h);
}

inline void negate(int n, double* e) {
  for (int i = 0; i < n; ++i) e[i] = -e[i];
}

inline int expansion_sign(int n, const double* e) { return n == 0 ? 0 : sign_of(e[n - 1]); }

}  // namespace tecido::expansion
