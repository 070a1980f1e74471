// The projected barycentric quadratics (core/geometry/ccd/projected_quadratics.h): their error
// bound against exact integer arithmetic, and at a coplanar instant the barycentric
// coordinates they give (num / den) against the contact point built at that instant.
#include "core/geometry/ccd/projected_quadratics.h"

#include <gtest/gtest.h>

#include <random>

namespace tecido {
namespace {

using I128 = __int128;

// det2 of the integer vectors u, v on the axes (i, j).
I128 det2(const double* u, const double* v, int i, int j) {
  return static_cast<I128>(u[i]) * static_cast<I128>(v[j]) - static_cast<I128>(u[j]) * static_cast<I128>(v[i]);
}

TEST(CcdProjectedQuadratics, ErrorBoundHoldsAgainstExactIntegers) {
  // Integer coordinates below 2^40: the differences are exact, the 2-D cross products below
  // 2^83 are exact in __int128; twice the middle coefficient is an integer.
  std::mt19937_64 rng(6502);
  std::uniform_int_distribution<long long> u(-(1LL << 40), 1LL << 40);
  const int pairs[2][5][2] = {{{CcdSystem::X, CcdSystem::Y}, {CcdSystem::Z, CcdSystem::Y}, {CcdSystem::X, CcdSystem::Z},
                               {CcdSystem::P, CcdSystem::Q}, {CcdSystem::P, CcdSystem::Q}},
                              {{CcdSystem::X, CcdSystem::Y}, {CcdSystem::Z, CcdSystem::Y}, {CcdSystem::X, CcdSystem::Z},
                               {CcdSystem::P, CcdSystem::Y}, {CcdSystem::X, CcdSystem::Q}}};
  for (int k = 0; k < 20000; ++k) {
    CcdQuery q;
    q.kind = k % 2 ? CcdKind::EdgeEdge : CcdKind::VertexFace;
    for (auto* x : {&q.x0, &q.x1})
      for (Vec3& p : *x) p = Vec3(static_cast<double>(u(rng)), static_cast<double>(u(rng)), static_cast<double>(u(rng)));
    CcdSystem s;
    ASSERT_EQ(prepare_ccd_system(q, s), CcdPrepared::Ok);
    double c[3][kCcdMaxQuadratics];
    CcdProjectedQuadratics pq;
    ccd_projected_quadratics(s, c, pq);
    const int i = (pq.axis + 1) % 3, j = (pq.axis + 2) % 3;
    for (int n = 0; n < kCcdMaxQuadratics; ++n) {
      const int* uv = pairs[k % 2][n];
      const I128 e0 = det2(s.d[0][uv[0]], s.d[0][uv[1]], i, j);
      const I128 e1x2 = det2(s.d[0][uv[0]], s.d[1][uv[1]], i, j) + det2(s.d[1][uv[0]], s.d[0][uv[1]], i, j);
      const I128 e2 = det2(s.d[1][uv[0]], s.d[1][uv[1]], i, j);
      const long double bound = pq.err[n].e0;
      EXPECT_LE(std::fabs(c[0][n] - static_cast<long double>(e0)), bound) << k << " " << n;
      EXPECT_LE(std::fabs(2.0L * c[1][n] - static_cast<long double>(e1x2)), 2.0L * bound) << k << " " << n;
      EXPECT_LE(std::fabs(c[2][n] - static_cast<long double>(e2)), bound) << k << " " << n;
    }
  }
}

TEST(CcdProjectedQuadratics, GiveTheBarycentricCoordinatesAtACoplanarInstant) {
  // Vertex-face with everything at rest (so t does not matter): p = a + u X + v Y with
  // (u, v) = (0.25, 0.375), dyadic, so p is exact; u = num1 / den, v = num2 / den,
  // w = num3 / den = 1 - u - v = 0.375.
  const Vec3 a(0.5, -1, 2), x(1, 0.5, 0.25), y(-0.5, 1, 0.75);
  const Vec3 p = a + 0.25 * x + 0.375 * y;
  CcdQuery q;
  q.kind = CcdKind::VertexFace;
  q.x0 = q.x1 = {p, a, a + x, a + y};
  CcdSystem s;
  ASSERT_EQ(prepare_ccd_system(q, s), CcdPrepared::Ok);
  double c[3][kCcdMaxQuadratics];
  CcdProjectedQuadratics pq;
  ccd_projected_quadratics(s, c, pq);
  EXPECT_EQ(pq.count, 4);
  EXPECT_NEAR(c[0][1] / c[0][0], 0.25, 1e-15);
  EXPECT_NEAR(c[0][2] / c[0][0], 0.375, 1e-15);
  EXPECT_NEAR(c[0][3] / c[0][0], 0.375, 1e-15);
  // Edge-edge: a0 + u X meets b0 + v (b1 - b0) at u = 0.75, v = 0.25: 1 - u and 1 - v too.
  const Vec3 a0(0, 0, 0), ea(2, 1, 0.5), eb(-1, 2, 1);
  const Vec3 m = a0 + 0.75 * ea, b0 = m - 0.25 * eb;
  q.kind = CcdKind::EdgeEdge;
  q.x0 = q.x1 = {a0, a0 + ea, b0, b0 + eb};
  ASSERT_EQ(prepare_ccd_system(q, s), CcdPrepared::Ok);
  ccd_projected_quadratics(s, c, pq);
  EXPECT_EQ(pq.count, 5);
  EXPECT_NEAR(c[0][1] / c[0][0], 0.75, 1e-15);
  EXPECT_NEAR(c[0][2] / c[0][0], 0.25, 1e-15);
  EXPECT_NEAR(c[0][3] / c[0][0], 0.25, 1e-15);
  EXPECT_NEAR(c[0][4] / c[0][0], 0.75, 1e-15);
}

}  // namespace
}  // namespace tecido
