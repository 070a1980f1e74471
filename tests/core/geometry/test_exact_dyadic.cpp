// Exact dyadic arithmetic: signs against __int128 on integer-valued doubles at every scale,
// algebraic identities that must hold exactly for doubles spread over the whole exponent range,
// comparisons against the (exact) comparison of doubles, and the extremes of the capacity bound.
#include "core/geometry/exact_dyadic.h"

#include <gtest/gtest.h>

#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>

namespace tecido {
namespace {

/// A double with random sign, random 53-bit significand and an exponent uniform over the whole
/// range (subnormals and exact zeros included now and then).
double wild(std::mt19937_64& g) {
  if (g() % 50 == 0) return 0.0;
  const double m = 1.0 + static_cast<double>(g() >> 12) * 0x1p-52;  // [1, 2)
  const int e = -1074 + static_cast<int>(g() % (1023 + 1074 + 1));
  const double x = std::ldexp(m, e);  // rounds when subnormal: still some double
  return (g() & 1) ? -x : x;
}

int sign(double x) { return (x > 0) - (x < 0); }

TEST(Dyadic, ZeroAndSingleDoubles) {
  EXPECT_EQ(Dyadic().sign(), 0);
  EXPECT_EQ(Dyadic(0.0).sign(), 0);
  EXPECT_EQ(Dyadic(-0.0).sign(), 0);
  for (double x : {1.0, -2.5, 0x1p-1074, -0x1p-1074, DBL_MAX, -DBL_MAX, 0x1p-1022, 3.0e-310}) {
    EXPECT_EQ(Dyadic(x).sign(), sign(x)) << x;
    EXPECT_EQ((Dyadic(x) - Dyadic(x)).sign(), 0) << x;
    long e = 0;
    const double m = Dyadic(x).approx_mantissa(&e);
    EXPECT_EQ(std::ldexp(m, static_cast<int>(e)), x) << x;  // one double: the approximation is exact
  }
  const double nan = std::nan(""), inf = HUGE_VAL;
  EXPECT_THROW(Dyadic{nan}, std::domain_error);
  EXPECT_THROW(Dyadic{inf}, std::domain_error);
  EXPECT_THROW(Dyadic{-inf}, std::domain_error);
}

TEST(Dyadic, SignsMatchInt128AtEveryScale) {
  // a b - c d + e for integers below 2^40, all scaled by 2^k: the sign is that of the integer
  // expression (scaling by a power of two keeps signs), computed exactly in __int128.
  std::mt19937_64 g(11);
  for (int trial = 0; trial < 20000; ++trial) {
    std::int64_t v[5];
    for (auto& x : v) x = static_cast<std::int64_t>(g() % (1ULL << 40)) - (1LL << 39);
    if (trial % 3 == 0) v[4] = 0;
    if (trial % 5 == 0) v[3] = v[0], v[2] = v[1], v[4] = 0;  // an exact cancellation
    const __int128 exact = static_cast<__int128>(v[0]) * v[1] - static_cast<__int128>(v[2]) * v[3] + v[4];
    const int want = (exact > 0) - (exact < 0);
    const int k = -480 + static_cast<int>(g() % 960);  // products of two scale by 2^2k: e too
    const Dyadic a(std::ldexp(double(v[0]), k)), b(std::ldexp(double(v[1]), k));
    const Dyadic c(std::ldexp(double(v[2]), k)), d(std::ldexp(double(v[3]), k));
    const Dyadic e(std::ldexp(double(v[4]), 2 * k));
    ASSERT_EQ((a * b - c * d + e).sign(), want) << trial;
  }
}

TEST(Dyadic, IdentitiesHoldExactlyOverTheWholeExponentRange) {
  std::mt19937_64 g(12);
  for (int trial = 0; trial < 20000; ++trial) {
    const double x = wild(g), y = wild(g), z = wild(g);
    const Dyadic a(x), b(y), c(z);
    ASSERT_EQ(((a + b) * (a - b) - (a * a - b * b)).sign(), 0);
    ASSERT_EQ(((a + b) + c - (a + (b + c))).sign(), 0);
    ASSERT_EQ((a * (b + c) - (a * b + a * c)).sign(), 0);
    ASSERT_EQ(((a * b) * c - a * (b * c)).sign(), 0);
    // Comparison of doubles is exact, so it is an independent truth for sign(x - y).
    ASSERT_EQ(compare(a, b), (x > y) - (x < y));
    ASSERT_EQ((a * b).sign(), sign(x) * sign(y));
    ASSERT_EQ((-a).sign(), -sign(x));
    ASSERT_EQ(a.abs().sign(), x != 0.0 ? 1 : 0);
    ASSERT_EQ(a.times_sign(-1).sign(), -sign(x));
  }
}

TEST(Dyadic, TinyTermsSurviveHugeOnes) {
  const Dyadic big(1e300), tiny(1e-300), smallest(0x1p-1074);
  EXPECT_EQ((big + tiny - big).sign(), 1);
  EXPECT_EQ((big - tiny - big).sign(), -1);
  EXPECT_EQ((big * big * big - tiny - big * big * big).sign(), -1);
  // Degree 5 and 6 at both ends of the range: no overflow, no underflow, within capacity.
  const Dyadic tiny5 = smallest * smallest * smallest * smallest * smallest;
  EXPECT_EQ(tiny5.sign(), 1);
  const Dyadic top(DBL_MAX), top6 = top * top * top * top * top * top;
  const Dyadic bottom6 = tiny5 * smallest;
  const Dyadic spread = top6 + bottom6;
  EXPECT_EQ((spread - top6).sign(), 1);
  EXPECT_EQ((spread - top6 - bottom6).sign(), 0);
  EXPECT_LE(spread.limbs(), Dyadic::kMaxLimbs);
  EXPECT_EQ((top6 - top * top * top * (top * top * top)).sign(), 0);
}

TEST(Dyadic, CopiesAreIndependent) {
  Dyadic a(3.0);
  const Dyadic b = a;
  a = a - Dyadic(5.0);
  EXPECT_EQ(a.sign(), -1);
  EXPECT_EQ(b.sign(), 1);
  EXPECT_EQ(compare(b, Dyadic(3.0)), 0);
}

}  // namespace
}  // namespace tecido
