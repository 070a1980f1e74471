// make_bounded_plane: an orthonormal frame from any valid (normal, forward), including a forward
// within 1e-9 rad of the normal, and idempotent, so a plane written at full precision and read
// back is the same plane bit for bit (the plane-case files of `tecido plane` rely on it).
#include "core/geometry/bounded_plane.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido {
namespace {

void expect_orthonormal(const BoundedPlane& p, const std::string& what) {
  EXPECT_NEAR(p.normal.norm(), 1.0, 4e-16) << what;
  EXPECT_NEAR(p.forward.norm(), 1.0, 4e-16) << what;
  EXPECT_LE(std::abs(p.normal.dot(p.forward)), 4e-16) << what;
}

void expect_same(const BoundedPlane& a, const BoundedPlane& b, const std::string& what) {
  EXPECT_EQ(a.normal, b.normal) << what;
  EXPECT_EQ(a.forward, b.forward) << what;
  EXPECT_EQ(a.position, b.position) << what;
}

TEST(BoundedPlane, FrameIsOrthonormalAndRebuildingItChangesNothing) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-10, 10);
  std::uniform_int_distribution<int> expo(-12, 0);
  for (int t = 0; t < 20000; ++t) {
    const Vec3 n(u(rng), u(rng), u(rng));
    Vec3 f(u(rng), u(rng), u(rng));
    if (t % 2) f = n * u(rng) + Vec3(u(rng), u(rng), u(rng)) * std::pow(10.0, expo(rng));  // nearly parallel
    if (n.normalized().cross(f.normalized()).norm() < 1e-9) continue;  // the readers reject these
    const BoundedPlane p = make_bounded_plane(Vec3(1, 2, 3), n, f, Vec2(1, 1), 0);
    expect_orthonormal(p, "case " + std::to_string(t));
    // The forward direction is the input's component orthogonal to the normal.
    const Vec3 g = f - n.normalized() * n.normalized().dot(f);
    EXPECT_GT(p.forward.dot(g.normalized()), 1.0 - 1e-6) << t;
    expect_same(make_bounded_plane(p.position, p.normal, p.forward, p.half_extents, p.friction), p,
                "rebuilt case " + std::to_string(t));
  }
}

TEST(BoundedPlane, ForwardOneNanoradianOffTheNormalStillGivesAnOrthogonalFrame) {
  // One Gram-Schmidt pass leaves |n.f| ~ 1e-7 here; two leave it at rounding level.
  const BoundedPlane p = make_bounded_plane(Vec3::Zero(), Vec3(0, 1e-9, 1), Vec3(0, 0, 0.1), Vec2(1, 1), 0);
  expect_orthonormal(p, "nearly parallel");
  EXPECT_NEAR(std::abs(p.forward.y()), 1.0, 1e-12);
}

TEST(BoundedPlane, UnitInputsAreKeptExactly) {
  const Vec3 n = Vec3(0.3, -0.4, 1.2).normalized();
  const BoundedPlane p = make_bounded_plane(Vec3::Zero(), n, Vec3::UnitX(), Vec2(1, 1), 0);
  EXPECT_EQ(p.normal, n);
  const BoundedPlane q = make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(1, 1), 0);
  EXPECT_EQ(q.normal, Vec3::UnitZ());
  EXPECT_EQ(q.forward, Vec3::UnitX());
}

}  // namespace
}  // namespace tecido
