// The exact side of a point: points exactly on tilted planes (by construction) and one ulp off,
// small integers at every scale against int64 arithmetic, differences that overflow.
#include "core/geometry/plane_side.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace tecido {
namespace {

BoundedPlane plane(const Vec3& position, const Vec3& normal) {
  BoundedPlane p;
  p.position = position;
  p.normal = normal;
  return p;
}

TEST(PlaneSide, AxisAligned) {
  const BoundedPlane p = plane(Vec3(0, 0, 0.25), Vec3::UnitZ());
  EXPECT_EQ(plane_side_sign(p, Vec3(3, -2, 0.5)), 1);
  EXPECT_EQ(plane_side_sign(p, Vec3(3, -2, 0.0)), -1);
  EXPECT_EQ(plane_side_sign(p, Vec3(3, -2, 0.25)), 0);
  EXPECT_EQ(plane_side_sign(p, Vec3(3, -2, std::nextafter(0.25, 1.0))), 1);
}

TEST(PlaneSide, ExactlyOnATiltedPlaneAndOneUlpOff) {
  // n = (k, k, k), k = 1/sqrt(3) rounded; x + y + z = 0 exactly, so n.x = k (x + y + z) = 0,
  // although the rounded products do not cancel. Moving z by one ulp gives the sign of that ulp.
  const double k = 1.0 / std::sqrt(3.0);
  const BoundedPlane p = plane(Vec3::Zero(), Vec3(k, k, k));
  for (const int m : {-1000, -500, -60, 0, 60, 500, 960}) {
    const Vec3 x(std::ldexp(1 + 0x1p-52, m), -std::ldexp(1.0, m), -std::ldexp(0x1p-52, m));
    EXPECT_EQ(plane_side_sign(p, x), 0) << m;
    EXPECT_EQ(plane_side_sign(p, Vec3(x.x(), x.y(), std::nextafter(x.z(), INFINITY))), 1) << m;
    EXPECT_EQ(plane_side_sign(p, Vec3(x.x(), x.y(), std::nextafter(x.z(), -INFINITY))), -1) << m;
    EXPECT_EQ(detail::plane_side_sign_exact(p, x), 0) << m;
  }
}

TEST(PlaneSide, SmallIntegersAtEveryScaleAgainstInt64) {
  std::mt19937_64 g(5);
  auto pick = [&g](int lo, int hi) { return lo + static_cast<int>(g() % (hi - lo + 1)); };
  for (int trial = 0; trial < 20000; ++trial) {
    int n[3], P[3], x[3];
    std::int64_t s = 0;
    for (int c = 0; c < 3; ++c) {
      n[c] = pick(-3, 3);
      P[c] = pick(-4, 4);
      x[c] = pick(-4, 4);
      s += static_cast<std::int64_t>(n[c]) * (x[c] - P[c]);
    }
    const int want = (s > 0) - (s < 0);
    const int k = pick(-1070, 1000), j = pick(-300, 300);  // lengths by 2^k, the normal by 2^j
    auto v = [](const int* a, int e) { return Vec3(std::ldexp(a[0], e), std::ldexp(a[1], e), std::ldexp(a[2], e)); };
    const BoundedPlane p = plane(v(P, k), v(n, j));
    ASSERT_EQ(plane_side_sign(p, v(x, k)), want) << trial;
  }
}

TEST(PlaneSide, DifferencesThatOverflow) {
  // n = (1, 1, 0): s = (x - Px) + (y - Py); each difference is +-3.4e308, beyond the largest double.
  const BoundedPlane p = plane(Vec3(-1.7e308, 1.7e308, 0), Vec3(1, 1, 0));
  EXPECT_EQ(plane_side_sign(p, Vec3(1.7e308, -1.7e308, 0)), 0);
  EXPECT_EQ(plane_side_sign(p, Vec3(1.7e308, std::nextafter(-1.7e308, 0.0), 0)), 1);
  EXPECT_EQ(plane_side_sign(p, Vec3(std::nextafter(1.7e308, 0.0), -1.7e308, 0)), -1);
}

}  // namespace
}  // namespace tecido
