// The coplanarity cubic's Bernstein coefficients and their error bound
// (core/geometry/ccd/coplanarity_cubic.h), against exact integer arithmetic: with integer
// coordinates below 2^40 the difference vectors are exact, and the exact coefficients times 3
// are integers below 2^125 (__int128), while the double evaluation rounds its products. The
// bound must hold on every case (random, near-coplanar, and with a cancelling permanent), and
// the polynomial must be the volume of the tetrahedron at every time.
#include "core/geometry/ccd/coplanarity_cubic.h"
#include "core/geometry/ccd/system.h"

#include <gtest/gtest.h>

#include <random>

namespace tecido {
namespace {

using I128 = __int128;
struct IV {
  I128 x, y, z;
};
IV iv(const double* d) { return {static_cast<I128>(d[0]), static_cast<I128>(d[1]), static_cast<I128>(d[2])}; }
IV cross(const IV& a, const IV& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
I128 dot(const IV& a, const IV& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
IV add(const IV& a, const IV& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }

// 3 times the exact Bernstein coefficients, from the (exact) difference vectors of s.
void exact_times3(const CcdSystem& s, I128 out[4]) {
  const IV x0 = iv(s.d[0][CcdSystem::X]), x1 = iv(s.d[1][CcdSystem::X]);
  const IV y0 = iv(s.d[0][CcdSystem::Y]), y1 = iv(s.d[1][CcdSystem::Y]);
  const IV z0 = iv(s.d[0][CcdSystem::Z]), z1 = iv(s.d[1][CcdSystem::Z]);
  const IV c00 = cross(y0, z0), c11 = cross(y1, z1), sum = add(cross(y1, z0), cross(y0, z1));
  out[0] = 3 * dot(x0, c00);
  out[1] = dot(x1, c00) + dot(x0, sum);
  out[2] = dot(x0, c11) + dot(x1, sum);
  out[3] = 3 * dot(x1, c11);
}

CcdQuery integer_query(std::mt19937_64& rng, CcdKind kind, int bits, bool coplanar) {
  std::uniform_int_distribution<long long> u(-(1LL << bits), 1LL << bits);
  CcdQuery q;
  q.kind = kind;
  for (auto* x : {&q.x0, &q.x1})
    for (Vec3& p : *x) p = Vec3(static_cast<double>(u(rng)), static_cast<double>(u(rng)), static_cast<double>(u(rng)));
  if (coplanar) {
    // All points near the plane z = 3x - 5y (off by at most 1): the coefficients cancel
    // almost entirely while the permanents stay large.
    std::uniform_int_distribution<int> off(-1, 1);
    for (auto* x : {&q.x0, &q.x1})
      for (Vec3& p : *x) p.z() = 3 * p.x() - 5 * p.y() + off(rng);
  }
  return q;
}

TEST(CcdCoplanarityCubic, ErrorBoundHoldsAgainstExactIntegers) {
  std::mt19937_64 rng(8086);
  int cases = 0, tight = 0;
  for (int k = 0; k < 20000; ++k) {
    const CcdKind kind = k % 2 ? CcdKind::EdgeEdge : CcdKind::VertexFace;
    const CcdQuery q = integer_query(rng, kind, 36, k % 4 >= 2);
    CcdSystem s;
    ASSERT_EQ(prepare_ccd_system(q, s), CcdPrepared::Ok);
    double f[4];
    CcdErrorBound err;
    ccd_coplanarity_cubic(s, f, err);
    I128 exact[4];
    exact_times3(s, exact);
    for (int i = 0; i < 4; ++i) {
      // |f_i - exact_i / 3| <= e0, compared as |3 f_i - exact_i| <= 3 e0 in long double (64-bit
      // significand: 3 f_i is exact, exact_i rounds by far less than the bound).
      const long double diff = std::fabs(3.0L * f[i] - static_cast<long double>(exact[i]));
      EXPECT_LE(diff, 3.0L * err.e0) << "case " << k << " coefficient " << i;
      tight += diff > 0.1L * err.e0;
    }
    ++cases;
  }
  EXPECT_EQ(cases, 20000);
  EXPECT_GT(tight, 0);  // the bound is not vacuous: some errors come within a tenth of it
}

TEST(CcdCoplanarityCubic, IsTheTetrahedronVolumeAtEveryTime) {
  // f(t) = sum b_i B_i(t) against det(X(t), Y(t), Z(t)) computed directly.
  std::mt19937_64 rng(12);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int k = 0; k < 200; ++k) {
    CcdQuery q;
    q.kind = k % 2 ? CcdKind::EdgeEdge : CcdKind::VertexFace;
    for (auto* x : {&q.x0, &q.x1})
      for (Vec3& p : *x) p = Vec3(u(rng), u(rng), u(rng));
    CcdSystem s;
    ASSERT_EQ(prepare_ccd_system(q, s), CcdPrepared::Ok);
    double f[4];
    CcdErrorBound err;
    ccd_coplanarity_cubic(s, f, err);
    for (const double t : {0.0, 0.125, 0.5, 0.7, 1.0}) {
      Vec3 v[3];
      for (int j = 0; j < 3; ++j)
        for (int c = 0; c < 3; ++c) v[j][c] = (1 - t) * s.d[0][j][c] + t * s.d[1][j][c];
      const double direct = v[0].dot(v[1].cross(v[2]));
      const double b = (1 - t) * (1 - t) * (1 - t) * f[0] + 3 * t * (1 - t) * (1 - t) * f[1] +
                       3 * t * t * (1 - t) * f[2] + t * t * t * f[3];
      EXPECT_NEAR(b, direct, 1e-12) << k << " t " << t;
    }
  }
}

}  // namespace
}  // namespace tecido
