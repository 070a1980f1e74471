// The cubic root of core's continuous collision test (core/geometry/ccd/cubic_root.h): rule J
// brackets the root it returns by [a, b] with the root at least h = 4 tol inside each end, so it
// must come back within tol of the true root (then the first bracket tried, of width 3 * 2^-46
// at the top level, certifies). Cubics built as (s - r) q(s) with q > 0 on [0, 1]: by hand, with
// r the root up to the rounding of the coefficients (far below tol), and at random, against the
// root of the rounded coefficients found by bisection in long double. Among them the cases where
// the iteration stops on its predicted error rather than on a step within tol, which is what
// this test watches: loosened, that stop fails both tests.
#include "core/geometry/ccd/cubic_root.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido {
namespace {

/// Bernstein coefficients on [0, 1] of a0 + a1 s + a2 s^2 + a3 s^3.
void bernstein_of(const double a[4], double b[4]) {
  b[0] = a[0];
  b[1] = a[0] + a[1] / 3.0;
  b[2] = a[0] + 2.0 * a[1] / 3.0 + a[2] / 3.0;
  b[3] = a[0] + a[1] + a[2] + a[3];
}

/// (s - r)(c0 + c1 s + c2 s^2) times `sign`, as Bernstein coefficients.
void cubic_with_root(double r, double c0, double c1, double c2, double sign, double b[4]) {
  const double a[4] = {sign * -r * c0, sign * (c0 - r * c1), sign * (c1 - r * c2), sign * c2};
  bernstein_of(a, b);
}

TEST(CcdCubicRoot, HandWorkedCubics) {
  const double tol = 0x1p-48;
  double b[4];
  // s - 0.3 times 1: a line (Newton exact in one step).
  cubic_with_root(0.3, 1.0, 0.0, 0.0, 1.0, b);
  EXPECT_NEAR(ccd_cubic_root(b, tol), 0.3, tol);
  // (s - 0.7)(1 + s + s^2), falling (sign -1): convex, far from its regula falsi start.
  cubic_with_root(0.7, 1.0, 1.0, 1.0, -1.0, b);
  EXPECT_NEAR(ccd_cubic_root(b, tol), 0.7, tol);
  // (s - 0.01)(0.001 + s^2): almost flat at the root (p' = 0.0011 there), near the start.
  cubic_with_root(0.01, 0.001, 0.0, 1.0, 1.0, b);
  EXPECT_NEAR(ccd_cubic_root(b, tol), 0.01, tol);
  // (s - 0.999)(0.5 - 0.4 s): the root next to the end of the interval.
  cubic_with_root(0.999, 0.5, -0.4, 0.0, 1.0, b);
  EXPECT_NEAR(ccd_cubic_root(b, tol), 0.999, tol);
}

/// The root in [0, 1] of the Bernstein cubic b (b[0], b[3] of opposite signs) by bisection in
/// long double (64-bit significand) on the exact coefficients: the truth for the test below.
long double bisected_root(const double b[4]) {
  const auto at = [b](long double s) {
    const long double t = 1.0L - s;
    return t * t * t * b[0] + 3.0L * s * t * t * b[1] + 3.0L * s * s * t * b[2] + s * s * s * b[3];
  };
  long double lo = 0.0L, hi = 1.0L;
  const bool rising = b[0] < 0.0;
  for (int it = 0; it < 90; ++it) {
    const long double mid = 0.5L * (lo + hi);
    ((at(mid) < 0.0L) == rising ? lo : hi) = mid;
  }
  return 0.5L * (lo + hi);
}

TEST(CcdCubicRoot, WithinToleranceOnRandomCubics) {
  // q = c0 + c1 s + c2 s^2 with c0 in [0.25, 1.25] and |c1| + |c2| <= c0 / 2, so q >= c0 / 2 on
  // [0, 1]: one sign change, not always monotone. Double precision cannot place a root closer
  // than its evaluation error over |p'|: that slack (8 eps sum |b_i| / |p'(r)|, a few 1e-16
  // here) is allowed on top of tol, and stays far below the errors an early stop would leave.
  std::mt19937_64 rng(4104);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double tols[] = {0x1p-48, 0x1p-44, 0x1p-40};
  int cases = 0;
  for (int k = 0; k < 20000; ++k) {
    const double r = 0.001 + 0.998 * unit(rng);
    const double c0 = 0.25 + unit(rng), c2 = (unit(rng) - 0.5) * 0.5 * c0;
    const double c1 = (unit(rng) - 0.5) * (c0 - 2.0 * std::fabs(c2));
    double b[4];
    cubic_with_root(r, c0, c1, c2, k % 2 ? 1.0 : -1.0, b);
    ASSERT_LT(b[0] * b[3], 0.0) << k;
    const long double truth = bisected_root(b);
    const double slope = c0 + r * (c1 + r * c2);  // |p'(r)| = q(r) >= c0 / 2
    const double slack = 8.0 * 0x1p-53 * (std::fabs(b[0]) + std::fabs(b[1]) + std::fabs(b[2]) + std::fabs(b[3])) / slope;
    const double tol = tols[k % 3];
    EXPECT_LE(std::fabs(static_cast<long double>(ccd_cubic_root(b, tol)) - truth), tol + slack) << k;
    ++cases;
  }
  EXPECT_EQ(cases, 20000);
}

}  // namespace
}  // namespace tecido
