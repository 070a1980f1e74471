// Segment vs bounded plane (DETECTACOLISÃO with the seed's slips fixed): hand-worked cases,
// hand-worked border cases at every scale (crossings exactly on an edge or a corner and one ulp
// either side, in-plane segments touching the border, end points on the plane), and an
// independent exact truth: small integers scaled by powers of two, decided in __int128
// rationals the way the exact referee defines the test (reference/exact_referee.h).
#include "core/geometry/segment_plane.h"

#include "core/geometry/segment_plane_seed.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <tuple>
#include <utility>
#include <vector>

namespace tecido {
namespace {

// Unit floor: z = 0, |x| <= 1, |y| <= 0.5 (forward = x, right = z x x = y).
BoundedPlane floor_plane() { return make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(1.0, 0.5), 0.0); }

TEST(SegmentPlane, RightIsNormalCrossForward) {
  EXPECT_EQ(floor_plane().right(), Vec3::UnitY());
}

TEST(SegmentPlane, CrossingInsideAtTheRightFraction) {
  const auto h = segment_plane(floor_plane(), Vec3(0.2, 0.1, 1.0), Vec3(0.2, 0.1, -3.0));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.25);
}

TEST(SegmentPlane, BothFromBelowToo) {  // two-sided
  const auto h = segment_plane(floor_plane(), Vec3(0, 0, -1.0), Vec3(0, 0, 1.0));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
}

TEST(SegmentPlane, SameSideNeverHits) {  // the seed's SIGNAL(p1) = SIGNAL(p2) slip, fixed
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, 0, 1), Vec3(0, 0, 0.5)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, 0, -1), Vec3(0.1, 0, -0.5)).hit);
}

TEST(SegmentPlane, CrossingOutsideTheRectangleMisses) {
  // Through the plane at x = 1.5 (beyond +hx) and at x = -1.5 (the missing lower bound of the seed).
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(1.5, 0, 1), Vec3(1.5, 0, -1)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(-1.5, 0, 1), Vec3(-1.5, 0, -1)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, -0.75, 1), Vec3(0, -0.75, -1)).hit);
}

TEST(SegmentPlane, CrossingTheBorderDiagonally) {
  // From inside-above to outside-below: crosses z=0 at x = 1.25 -> miss; at x = 0.75 -> hit.
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0.5, 0, 1), Vec3(2.0, 0, -1)).hit);
  const auto h = segment_plane(floor_plane(), Vec3(0.5, 0, 1), Vec3(1.0, 0, -1));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
}

TEST(SegmentPlane, ExactlyOnTheBorderAndCornerCount) {  // closed rectangle
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(1.0, 0, 1), Vec3(1.0, 0, -1)).hit);
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(1.0, 0.5, 1), Vec3(1.0, 0.5, -1)).hit);     // corner
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(-1.0, -0.5, 1), Vec3(-1.0, -0.5, -1)).hit); // opposite corner
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(1.0, 0.5000001, 1), Vec3(1.0, 0.5000001, -1)).hit);
}

TEST(SegmentPlane, StartingOnThePlane) {
  const auto h = segment_plane(floor_plane(), Vec3(0.3, 0.3, 0.0), Vec3(0.3, 0.3, -1.0));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t, 0.0);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(3, 0, 0.0), Vec3(3, 0, -1.0)).hit);  // on the plane, outside
}

TEST(SegmentPlane, EndingOnThePlane) {
  const auto h = segment_plane(floor_plane(), Vec3(0.3, 0.3, 2.0), Vec3(0.3, 0.3, 0.0));
  ASSERT_TRUE(h.hit);
  EXPECT_EQ(h.t, 1.0);
}

TEST(SegmentPlane, ParallelAboveMisses) {
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(-2, 0, 0.1), Vec3(2, 0, 0.1)).hit);
}

TEST(SegmentPlane, LyingInThePlaneHitsAtTheFirstPointInside) {
  // From x = -3 to x = 1 along y = 0 in the plane: enters the rectangle at x = -1, t = 0.5.
  const auto h = segment_plane(floor_plane(), Vec3(-3, 0, 0), Vec3(1, 0, 0));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(-3, 0.6, 0), Vec3(1, 0.6, 0)).hit);
  const auto inside = segment_plane(floor_plane(), Vec3(0, 0, 0), Vec3(0.5, 0, 0));
  ASSERT_TRUE(inside.hit);
  EXPECT_EQ(inside.t, 0.0);
}

TEST(SegmentPlane, GrazingTheEdgeFromOutside) {
  // Touches the plane only at the border point (1, 0, 0): closed rectangle -> hit at t = 0.5.
  const auto h = segment_plane(floor_plane(), Vec3(1, 0, 1), Vec3(1, 0, -1));
  ASSERT_TRUE(h.hit);
  EXPECT_DOUBLE_EQ(h.t, 0.5);
  // Passing just outside the corner, diagonally.
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(1.001, 0.501, 1), Vec3(1.001, 0.501, -1)).hit);
}

TEST(SegmentPlane, TiltedPlaneFarFromOrigin) {
  // A plane tilted 45 degrees about y, centred at (1e6, 2e6, -5e5).
  const Vec3 c(1e6, 2e6, -5e5);
  const Vec3 n = Vec3(1, 0, 1).normalized();
  const BoundedPlane p = make_bounded_plane(c, n, Vec3(1, 0, -1), Vec2(2.0, 1.0), 0.0);
  const Vec3 a = c + 3.0 * n + 0.5 * p.forward + 0.25 * p.right();
  const Vec3 b = c - 1.0 * n + 0.5 * p.forward + 0.25 * p.right();
  const auto h = segment_plane(p, a, b);
  ASSERT_TRUE(h.hit);
  EXPECT_NEAR(h.t, 0.75, 1e-9);
  const Vec3 a2 = c + 3.0 * n + 2.5 * p.forward;
  const Vec3 b2 = c - 1.0 * n + 2.5 * p.forward;
  EXPECT_FALSE(segment_plane(p, a2, b2).hit);
}

TEST(SegmentPlane, DegenerateSegment) {
  EXPECT_TRUE(segment_plane(floor_plane(), Vec3(0, 0, 0), Vec3(0, 0, 0)).hit);
  EXPECT_FALSE(segment_plane(floor_plane(), Vec3(0, 0, 1), Vec3(0, 0, 1)).hit);
}

// ---------------------------------------------------------------------------------------
// Border cases, hand-worked. The "diagonal" plane: P = 0, n = (1/2, 1/2, 0), f = (1/2, -1/2, 0),
// neither unit nor what make_bounded_plane would produce, but the test is defined on the stored
// doubles: r = n x f = (0, 0, -1/2), and with d = (x, y, z), s = (x + y)/2, a = (x - y)/2,
// b = -z/2. With hx = 1, hy = 1/2 the rectangle is x + y = 0, |x - y| <= 2, |z| <= 1. Every
// coordinate below is dyadic, so each case is worked exactly by hand; all lengths are then
// scaled by 2^m (exact), which scales s, a, b, hx, hy alike and keeps every answer.

BoundedPlane diagonal_plane(int m) {
  BoundedPlane p;
  p.position = Vec3::Zero();
  p.normal = Vec3(0.5, 0.5, 0.0);
  p.forward = Vec3(0.5, -0.5, 0.0);
  p.half_extents = Vec2(std::ldexp(1.0, m), std::ldexp(0.5, m));
  return p;
}

struct BorderCase {
  const char* what;
  Vec3 p1, p2;
  bool hit;
  double t;  // when hit
};

std::vector<BorderCase> border_cases() {
  const double up = 0x1p-53, down = 0x1p-54;  // one ulp of 0.5 above it, below it
  return {
      // Crossing at t = 1/2 through (1, -1, 0): a = 1 = hx, on the edge.
      {"crossing on the edge", {1.5, -0.5, 0.25}, {0.5, -1.5, -0.25}, true, 0.5},
      // p2.x one ulp up: a = (1 - 2^-55) / (1 - 2^-54) > 1 at the crossing.
      {"edge, one ulp outside", {1.5, -0.5, 0.25}, {0.5 + up, -1.5, -0.25}, false, 0},
      // p2.x one ulp down: a = (1 + 2^-56) / (1 + 2^-55) < 1.
      {"edge, one ulp inside", {1.5, -0.5, 0.25}, {0.5 - down, -1.5, -0.25}, true, 0.5},
      // Through the corner (1, -1, -1): a = 1, b = 1/2.
      {"crossing at the corner", {1.5, -0.5, -0.75}, {0.5, -1.5, -1.25}, true, 0.5},
      // p2.z one ulp down: z = -1 - 2^-53 at the crossing, |b| = 1/2 + 2^-54.
      {"corner, one ulp outside", {1.5, -0.5, -0.75}, {0.5, -1.5, -1.25 - 0x1p-52}, false, 0},
      {"corner, one ulp inside", {1.5, -0.5, -0.75}, {0.5, -1.5, -1.25 + 0x1p-52}, true, 0.5},
      // In the plane (x = -y, so s = 0): (a, b) from (3, 0) to (1, 0), touching the edge at t = 1.
      {"in plane, ends on the edge", {3, -3, 0}, {1, -1, 0}, true, 1.0},
      {"in plane, ends one ulp short", {3, -3, 0}, {1 + 0x1p-52, -1 - 0x1p-52, 0}, false, 0},
      // In the plane, (a, b) from (2, 0) to (0, 1): meets the rectangle only at its corner (1, 1/2).
      {"in plane, touches the corner", {2, -2, 0}, {0, 0, -2}, true, 0.5},
      {"in plane, misses the corner by an ulp", {2, -2, 0}, {0, 0, -2 - 0x1p-51}, false, 0},
      {"in plane, cuts the corner by an ulp", {2, -2, 0}, {0, 0, -2 + 0x1p-51}, true, 0.5},
      // End points on the plane: on the edge (hit at that end), one ulp beyond it along the plane.
      {"starts on the edge", {1, -1, 0}, {1.5, -0.5, 0.25}, true, 0.0},
      {"ends on the edge", {1.5, -0.5, 0.25}, {1, -1, 0}, true, 1.0},
      {"starts one ulp beyond the edge", {1 + 0x1p-52, -1 - 0x1p-52, 0}, {1.5, -0.5, 0.25}, false, 0},
      // One ulp off the plane at the edge, then away: never on the plane.
      {"starts one ulp above, leaves", {1 + 0x1p-52, -1, 0}, {1.5, -0.5, 0.25}, false, 0},
      // A degenerate segment on the corner.
      {"a point on the corner", {1, -1, -1}, {1, -1, -1}, true, 0.0},
  };
}

TEST(SegmentPlaneBorder, HandWorkedCasesAtEveryScale) {
  for (const int m : {-1000, -600, -200, -60, 0, 60, 200, 600, 1000}) {
    const BoundedPlane pl = diagonal_plane(m);
    for (const BorderCase& c : border_cases()) {
      const Vec3 p1 = c.p1 * std::ldexp(1.0, m), p2 = c.p2 * std::ldexp(1.0, m);
      ASSERT_EQ(p1 * std::ldexp(1.0, -m), c.p1) << "scaling must be exact";
      ASSERT_EQ(p2 * std::ldexp(1.0, -m), c.p2) << "scaling must be exact";
      const SegmentPlaneHit h = segment_plane(pl, p1, p2);
      EXPECT_EQ(h.hit, c.hit) << c.what << " at scale 2^" << m;
      if (h.hit && c.hit) {
        EXPECT_NEAR(h.t, c.t, 1e-15) << c.what << " at scale 2^" << m;
      }
      // The unfiltered exact path agrees.
      EXPECT_EQ(detail::segment_plane_exact(pl, p1, p2).hit, c.hit) << c.what << " at scale 2^" << m;
    }
  }
}

TEST(SegmentPlaneBorder, TheSeedsFloatingPointTestMissesSomeOfThem) {
  // Not a requirement on the seed's test, a record of why the exact decision exists: at scale 1
  // at least one of the hand-worked border cases is decided wrongly by rounding.
  int wrong = 0;
  const BoundedPlane pl = diagonal_plane(0);
  for (const BorderCase& c : border_cases()) wrong += segment_plane_seed(pl, c.p1, c.p2).hit != c.hit;
  EXPECT_GT(wrong, 0);
}

TEST(SegmentPlaneBorder, SubnormalRectangle) {
  // Floor z = 0 with half extents 4 and 2 units of 2^-1074 (the smallest subnormal).
  const double u = 0x1p-1074;
  const BoundedPlane pl = make_bounded_plane(Vec3::Zero(), Vec3::UnitZ(), Vec3::UnitX(), Vec2(4 * u, 2 * u), 0.0);
  // Crossing at t = 1/2 through (4u, 0, 0), then (4.5u, 0, 0), then through the corner (4u, 2u).
  EXPECT_TRUE(segment_plane(pl, Vec3(3 * u, 0, u), Vec3(5 * u, 0, -u)).hit);
  EXPECT_FALSE(segment_plane(pl, Vec3(3 * u, 0, u), Vec3(6 * u, 0, -u)).hit);
  EXPECT_TRUE(segment_plane(pl, Vec3(3 * u, u, u), Vec3(5 * u, 3 * u, -u)).hit);
  EXPECT_FALSE(segment_plane(pl, Vec3(3 * u, u, u), Vec3(5 * u, 4 * u, -u)).hit);
}

TEST(SegmentPlaneBorder, HugeCoordinatesWhoseDifferencesOverflow) {
  // The plane x = -1e308 (forward y, so |y| <= 1, |z| <= 1); the segment from x = 1.5e308 to
  // x = -1.5e308 crosses it at t = 2.5 / 3, where p1 - P = 2.5e308 overflows in floating point.
  const BoundedPlane pl = make_bounded_plane(Vec3(-1e308, 0, 0), Vec3::UnitX(), Vec3::UnitY(), Vec2(1, 1), 0.0);
  const SegmentPlaneHit on_edge = segment_plane(pl, Vec3(1.5e308, 1, 0), Vec3(-1.5e308, 1, 0));
  ASSERT_TRUE(on_edge.hit);
  EXPECT_NEAR(on_edge.t, 2.5 / 3.0, 1e-15);
  const double y = std::nextafter(1.0, 2.0);
  EXPECT_FALSE(segment_plane(pl, Vec3(1.5e308, y, 0), Vec3(-1.5e308, y, 0)).hit);
  EXPECT_TRUE(segment_plane(pl, Vec3(1.5e308, 1, 1), Vec3(-1.5e308, 1, 1)).hit);  // through the corner
  EXPECT_FALSE(segment_plane(pl, Vec3(1.5e308, 1, y), Vec3(-1.5e308, 1, y)).hit);
}

TEST(SegmentPlaneBorder, NonFiniteInputIsNoHit) {
  const BoundedPlane pl = floor_plane();
  EXPECT_FALSE(segment_plane(pl, Vec3(0, 0, 1), Vec3(0, 0, NAN)).hit);
  EXPECT_FALSE(segment_plane(pl, Vec3(0, 0, 1), Vec3(0, 0, -INFINITY)).hit);
}

// ---------------------------------------------------------------------------------------
// Independent exact truth: integer inputs, decided with __int128 rationals following the
// exact referee's definition literally (t = s1 / (s1 - s2), the crossing point's a and b
// compared with the half extents; in the plane, the Liang-Barsky interval of t), not the
// polynomial signs core uses.

struct Q {  // num / den, den > 0
  __int128 num, den;
};
Q q(__int128 n, __int128 d = 1) { return d < 0 ? Q{-n, -d} : Q{n, d}; }
int cmp(const Q& x, const Q& y) {
  const __int128 l = x.num * y.den, r = y.num * x.den;
  return (l > r) - (l < r);
}
Q add(const Q& x, const Q& y) { return q(x.num * y.den + y.num * x.den, x.den * y.den); }
Q mul(const Q& x, const Q& y) { return q(x.num * y.num, x.den * y.den); }
Q sub(const Q& x, const Q& y) { return add(x, q(-y.num, y.den)); }
Q abs(const Q& x) { return q(x.num < 0 ? -x.num : x.num, x.den); }

struct IntCase {
  std::int64_t P[3], n[3], f[3], h[2], p1[3], p2[3];
};

/// The exact answer for integer inputs (magnitudes small enough for __int128: |inputs| <= 12).
bool int_truth(const IntCase& c) {
  const std::int64_t r[3] = {c.n[1] * c.f[2] - c.n[2] * c.f[1], c.n[2] * c.f[0] - c.n[0] * c.f[2],
                             c.n[0] * c.f[1] - c.n[1] * c.f[0]};
  auto dot = [&](const std::int64_t* v, const std::int64_t* p) {
    std::int64_t s = 0;
    for (int k = 0; k < 3; ++k) s += v[k] * (p[k] - c.P[k]);
    return s;
  };
  const std::int64_t s1 = dot(c.n, c.p1), s2 = dot(c.n, c.p2);
  if ((s1 > 0 && s2 > 0) || (s1 < 0 && s2 < 0)) return false;
  const Q a1 = q(dot(c.f, c.p1)), a2 = q(dot(c.f, c.p2)), b1 = q(dot(r, c.p1)), b2 = q(dot(r, c.p2));
  const Q hx = q(c.h[0]), hy = q(c.h[1]);
  if (s1 == 0 && s2 == 0) {  // clip [0, 1] by -h <= v0 + t dv <= h on both axes
    Q lo = q(0), hi = q(1);
    for (const auto& [v0, v1, h] : {std::tuple{a1, a2, hx}, std::tuple{b1, b2, hy}}) {
      const Q dv = sub(v1, v0);
      if (dv.num == 0) {
        if (cmp(abs(v0), h) > 0) return false;
        continue;
      }
      Q t1 = mul(sub(q(-h.num, h.den), v0), q(dv.den, dv.num)), t2 = mul(sub(h, v0), q(dv.den, dv.num));
      if (cmp(t2, t1) < 0) std::swap(t1, t2);
      if (cmp(t1, lo) > 0) lo = t1;
      if (cmp(t2, hi) < 0) hi = t2;
    }
    return cmp(lo, hi) <= 0;
  }
  const Q t = q(s1, s1 - s2);
  const Q a = add(a1, mul(t, sub(a2, a1))), b = add(b1, mul(t, sub(b2, b1)));
  return cmp(abs(a), hx) <= 0 && cmp(abs(b), hy) <= 0;
}

/// Random integer cases in a tiny range, so that exact ties (an end point on the plane, a
/// crossing on an edge or a corner, a segment in the plane) are frequent.
std::vector<IntCase> int_cases(int count, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  auto pick = [&g](int lo, int hi) { return static_cast<std::int64_t>(lo + static_cast<int>(g() % (hi - lo + 1))); };
  std::vector<IntCase> out(count);
  for (IntCase& c : out) {
    const bool through_centre = g() % 2 == 0;  // p2 mirrors p1 about a point near P
    for (int k = 0; k < 3; ++k) {
      c.P[k] = pick(-2, 2);
      c.n[k] = pick(-2, 2);
      c.f[k] = pick(-2, 2);
      c.p1[k] = pick(-4, 4);
      c.p2[k] = through_centre ? 2 * (c.P[k] + pick(-1, 1)) - c.p1[k]
                               : (g() % 3 == 0 ? c.p1[k] : pick(-4, 4));  // often a common coordinate
    }
    if (c.n[0] == 0 && c.n[1] == 0 && c.n[2] == 0) c.n[2] = 1;
    c.h[0] = pick(0, 4);
    c.h[1] = pick(0, 4);
  }
  return out;
}

/// The case as doubles, lengths (P, p1, p2) scaled by 2^k, n by 2^j, f by 2^i, hx by 2^(k+i),
/// hy by 2^(k+i+j): s, a, b scale by 2^(k+j), 2^(k+i), 2^(k+i+j), and every comparison of the
/// test keeps its answer.
void scaled(const IntCase& c, int k, int j, int i, BoundedPlane& pl, Vec3& p1, Vec3& p2) {
  auto v = [](const std::int64_t* x, int e) {
    return Vec3(std::ldexp(double(x[0]), e), std::ldexp(double(x[1]), e), std::ldexp(double(x[2]), e));
  };
  pl.position = v(c.P, k);
  pl.normal = v(c.n, j);
  pl.forward = v(c.f, i);
  pl.half_extents = Vec2(std::ldexp(double(c.h[0]), k + i), std::ldexp(double(c.h[1]), k + i + j));
  p1 = v(c.p1, k);
  p2 = v(c.p2, k);
}

TEST(SegmentPlaneExactTruth, SmallIntegersAcrossScales) {
  const auto cases = int_cases(20000, 2024);
  // (k, j, i): unit scale, tiny and huge lengths, normals and forwards far from unit, and mixes
  // that leave the filter's range (|x| in [2^-150, 2^150]) so the exact path decides alone.
  const int scales[][3] = {{0, 0, 0},       {-3, -1, -2},    {40, -20, 10},   {-140, 0, 0},  {300, -250, 200},
                           {-1000, 0, 0},   {-1060, 300, 300}, {1000, 0, 0},  {900, -600, 100}, {-500, 500, -500}};
  long hits = 0, ties = 0;
  const std::uint64_t exact_before = segment_plane_exact_path_count();
  for (const IntCase& c : cases) {
    const bool truth = int_truth(c);
    hits += truth;
    for (const auto& sc : scales) {
      BoundedPlane pl;
      Vec3 p1, p2;
      scaled(c, sc[0], sc[1], sc[2], pl, p1, p2);
      ASSERT_EQ(segment_plane(pl, p1, p2).hit, truth)
          << "scale (" << sc[0] << "," << sc[1] << "," << sc[2] << ") P=" << pl.position.transpose() << " n="
          << pl.normal.transpose() << " f=" << pl.forward.transpose() << " h=" << pl.half_extents.transpose()
          << " p1=" << p1.transpose() << " p2=" << p2.transpose();
    }
  }
  ties = static_cast<long>(segment_plane_exact_path_count() - exact_before);
  // The set is not trivial: both answers occur, and many cases reach the exact path.
  EXPECT_GT(hits, 2000);
  EXPECT_LT(hits, 18000);
  EXPECT_GT(ties, 10000);
}

TEST(SegmentPlaneExactTruth, FilteredAndExactPathsAgreeOnRandomCases) {
  std::mt19937_64 g(99);
  auto uni = [&g](double a, double b) { return a + (b - a) * (static_cast<double>(g() >> 11) * 0x1p-53); };
  const std::uint64_t before = segment_plane_exact_path_count();
  const int n = 20000;
  for (int k = 0; k < n; ++k) {
    const Vec3 nrm = Vec3(uni(-1, 1), uni(-1, 1), uni(-1, 1)).normalized();
    const Vec3 fwd = nrm.cross(Vec3(uni(-1, 1), uni(-1, 1), uni(-1, 1))).normalized();
    const BoundedPlane pl = make_bounded_plane(Vec3(uni(-1, 1), uni(-1, 1), uni(-1, 1)), nrm, fwd,
                                               Vec2(uni(0.1, 2), uni(0.1, 2)), 0.0);
    const Vec3 p1(uni(-3, 3), uni(-3, 3), uni(-3, 3)), p2(uni(-3, 3), uni(-3, 3), uni(-3, 3));
    const std::uint64_t mid = segment_plane_exact_path_count();
    const SegmentPlaneHit fast = segment_plane(pl, p1, p2);
    const bool went_exact = segment_plane_exact_path_count() != mid;
    const SegmentPlaneHit exact = detail::segment_plane_exact(pl, p1, p2);
    ASSERT_EQ(fast.hit, exact.hit) << k;
    if (fast.hit && !went_exact) {
      EXPECT_GE(fast.t, 0.0);
      EXPECT_LE(fast.t, 1.0);
      EXPECT_NEAR(fast.t, exact.t, 1e-12) << k;
    }
  }
  // Random cases are decided by the filter: only the n calls of the exact path itself counted,
  // plus (almost) none from segment_plane.
  EXPECT_LT(segment_plane_exact_path_count() - before, static_cast<std::uint64_t>(n + n / 100));
}

}  // namespace
}  // namespace tecido
