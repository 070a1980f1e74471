// Exact-sign orientation predicates (core/geometry/orient_predicates.h) against independent
// exact truths: integer determinants in __int128 on inputs that are integers scaled by powers
// of two and shifted by offsets (both exact), coplanar/collinear points built exactly and then
// moved by one ulp, and extreme exponent ranges where the sign is known from the structure.
#include "core/geometry/orient_predicates.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>

namespace tecido {
namespace {

using i128 = __int128;

int sgn(i128 v) { return (v > 0) - (v < 0); }

struct IP3 {
  std::int64_t x, y, z;
};

/// Shewchuk's orient3d on integer points, exactly: det[a-d; b-d; c-d].
int ref_orient3d(const IP3& a, const IP3& b, const IP3& c, const IP3& d) {
  const i128 adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const i128 bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const i128 cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  return sgn(adx * (bdy * cdz - bdz * cdy) - ady * (bdx * cdz - bdz * cdx) +
             adz * (bdx * cdy - bdy * cdx));
}

int ref_orient2d(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                 std::int64_t cx, std::int64_t cy) {
  return sgn(static_cast<i128>(ax - cx) * (by - cy) - static_cast<i128>(ay - cy) * (bx - cx));
}

/// Exact map from integers to doubles: offset + i * 2^-k (the caller keeps it representable).
struct Map {
  double offset[3];
  int k[3];
  Vec3 operator()(const IP3& p) const {
    return {offset[0] + std::ldexp(static_cast<double>(p.x), -k[0]),
            offset[1] + std::ldexp(static_cast<double>(p.y), -k[1]),
            offset[2] + std::ldexp(static_cast<double>(p.z), -k[2])};
  }
};

/// Maps whose images are exact for |integer| <= 2^21: offsets 0, powers of two and
/// decimals up to 1e8, per-axis scales 2^-k, huge and tiny magnitudes.
std::vector<Map> exact_maps() {
  return {
      {{0, 0, 0}, {0, 0, 0}},
      {{0, 0, 0}, {40, 40, 40}},
      {{0, 0, 0}, {-300, -300, -300}},          // ~1e96 .. 1e97
      {{0, 0, 0}, {900, 900, 900}},             // ~1e-265: products underflow
      {{0, 0, 0}, {1050, 1050, 1050}},          // subnormal coordinates
      {{0, 0, 0}, {5, -200, 300}},              // different scale per axis
      {{0x1p20, -0x1p20, 0x1p25}, {20, 20, 20}},
      {{1e3, 1e3, -1e3}, {25, 25, 25}},
      {{1e5, -1e5, 1e5}, {20, 20, 20}},
      {{1e8, 1e8, 1e8}, {4, 4, 4}},
      {{-1e8, 3e7, 1e8}, {4, 6, 4}},
      {{0x1p31, 0x1p31, 0x1p31}, {0, 0, 0}},    // 2^31 + i: no bits to spare for products
      {{0x1p332, 0x1p332, -0x1p332}, {-300, -300, -300}},  // ~1e100 with 2^300 steps
  };
}

IP3 random_ip(std::mt19937_64& rng, std::int64_t range) {
  std::uniform_int_distribution<std::int64_t> d(-range, range);
  return {d(rng), d(rng), d(rng)};
}

TEST(OrientPredicates, SignConventionOrient3d) {
  const Vec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  // a, b, c counter-clockwise seen from +z; d below (z < 0) gives +1.
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(0, 0, -1)), 1);
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(0.3, 0.3, 1)), -1);
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(5, -7, 0)), 0);
  // Odd permutations flip the sign.
  EXPECT_EQ(orient3d_sign(b, a, c, Vec3(0, 0, -1)), -1);
  EXPECT_EQ(orient3d_sign(a, b, Vec3(0, 0, -1), c), -1);
}

TEST(OrientPredicates, SignConventionOrient2d) {
  EXPECT_EQ(orient2d_sign(0, 0, 1, 0, 0, 1), 1);   // counter-clockwise
  EXPECT_EQ(orient2d_sign(0, 0, 0, 1, 1, 0), -1);  // clockwise
  EXPECT_EQ(orient2d_sign(0, 0, 1, 1, 3, 3), 0);   // collinear
}

TEST(OrientPredicates, Orient3dMatchesIntegerDeterminant) {
  std::mt19937_64 rng(1);
  int checked = 0;
  for (const Map& m : exact_maps()) {
    for (int range : {2, 5, 1 << 20}) {
      for (int i = 0; i < 4000; ++i) {
        const IP3 a = random_ip(rng, range), b = random_ip(rng, range);
        const IP3 c = random_ip(rng, range), d = random_ip(rng, range);
        const int expected = ref_orient3d(a, b, c, d);
        const Vec3 fa = m(a), fb = m(b), fc = m(c), fd = m(d);
        ASSERT_EQ(orient3d_sign(fa, fb, fc, fd), expected) << "map offset " << m.offset[0];
        ASSERT_EQ(detail::orient3d_sign_bigint(fa, fb, fc, fd), expected);
        ++checked;
      }
    }
  }
  EXPECT_GT(checked, 100000);
}

TEST(OrientPredicates, Orient2dMatchesIntegerDeterminant) {
  std::mt19937_64 rng(2);
  for (const Map& m : exact_maps()) {
    for (int range : {2, 5, 1 << 20}) {
      for (int i = 0; i < 4000; ++i) {
        const IP3 a = random_ip(rng, range), b = random_ip(rng, range);
        const IP3 c = random_ip(rng, range);
        const int expected = ref_orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
        const Vec3 fa = m(a), fb = m(b), fc = m(c);
        ASSERT_EQ(orient2d_sign(fa[0], fa[1], fb[0], fb[1], fc[0], fc[1]), expected);
        ASSERT_EQ(detail::orient2d_sign_bigint(fa[0], fa[1], fb[0], fb[1], fc[0], fc[1]),
                  expected);
      }
    }
  }
}

// Points exactly on a plane (integer combinations), then one coordinate of d moved by one
// ulp: orient3d = -(d - a).n with n = (b-a)x(c-a), so the sign becomes -sign(step * n_k).
TEST(OrientPredicates, Orient3dOneUlpOffExactPlane) {
  std::mt19937_64 rng(3);
  std::uniform_int_distribution<int> small(-3, 3);
  int nonzero_cases = 0;
  for (const Map& m : exact_maps()) {
    for (int i = 0; i < 3000; ++i) {
      const IP3 a = random_ip(rng, 1000), b = random_ip(rng, 1000), c = random_ip(rng, 1000);
      const int s = small(rng), t = small(rng);
      const IP3 d = {a.x + s * (b.x - a.x) + t * (c.x - a.x), a.y + s * (b.y - a.y) + t * (c.y - a.y),
                     a.z + s * (b.z - a.z) + t * (c.z - a.z)};
      const Vec3 fa = m(a), fb = m(b), fc = m(c), fd = m(d);
      ASSERT_EQ(orient3d_sign(fa, fb, fc, fd), 0);
      const i128 n[3] = {
          static_cast<i128>(b.y - a.y) * (c.z - a.z) - static_cast<i128>(b.z - a.z) * (c.y - a.y),
          static_cast<i128>(b.z - a.z) * (c.x - a.x) - static_cast<i128>(b.x - a.x) * (c.z - a.z),
          static_cast<i128>(b.x - a.x) * (c.y - a.y) - static_cast<i128>(b.y - a.y) * (c.x - a.x)};
      for (int k = 0; k < 3; ++k) {
        for (int dir : {-1, 1}) {
          Vec3 moved = fd;
          moved[k] = std::nextafter(fd[k], dir > 0 ? INFINITY : -INFINITY);
          const int expected = -dir * sgn(n[k]);
          nonzero_cases += expected != 0;
          ASSERT_EQ(orient3d_sign(fa, fb, fc, moved), expected)
              << "axis " << k << " dir " << dir << " offset " << m.offset[0];
          ASSERT_EQ(detail::orient3d_sign_bigint(fa, fb, fc, moved), expected);
        }
      }
    }
  }
  EXPECT_GT(nonzero_cases, 100000);
}

// Collinear points moved by one ulp: orient2d = (a-c)x(b-c); moving c along x by e adds
// e*(ay - by), along y adds -e*(ax - bx).
TEST(OrientPredicates, Orient2dOneUlpOffExactLine) {
  std::mt19937_64 rng(4);
  std::uniform_int_distribution<int> small(-5, 5);
  for (const Map& m : exact_maps()) {
    for (int i = 0; i < 3000; ++i) {
      const IP3 a = random_ip(rng, 1 << 16), b = random_ip(rng, 1 << 16);
      const int s = small(rng);
      const IP3 c = {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), 0};
      const Vec3 fa = m(a), fb = m(b), fc = m(c);
      ASSERT_EQ(orient2d_sign(fa[0], fa[1], fb[0], fb[1], fc[0], fc[1]), 0);
      for (int dir : {-1, 1}) {
        const double cx = std::nextafter(fc[0], dir > 0 ? INFINITY : -INFINITY);
        const double cy = std::nextafter(fc[1], dir > 0 ? INFINITY : -INFINITY);
        EXPECT_EQ(orient2d_sign(fa[0], fa[1], fb[0], fb[1], cx, fc[1]),
                  dir * sgn(static_cast<i128>(a.y - b.y)));
        EXPECT_EQ(orient2d_sign(fa[0], fa[1], fb[0], fb[1], fc[0], cy),
                  -dir * sgn(static_cast<i128>(a.x - b.x)));
      }
    }
  }
}

// Coordinates v * 2^(base_c + step_c*g), v small, g in {0,1,2}, step_c either 0 or S for
// all axes: each monomial of the determinant is an integer times 2^(sum of bases + S*G),
// G the sum of the g's on axes with a nonzero step. With S far above the integers' bit
// count, the sign is that of the highest G whose integer sum is nonzero. These spans (up to
// ~1900 bits on one axis, subnormals, two wide axes and a narrow one) defeat expansion
// arithmetic and exercise the exponent-range checks and the big-integer stage.
struct Coded {
  std::int64_t v;
  int g;  // 0 on axes with step 0
};

template <int K>
int grouped_sign(const Coded (&rows)[K + 1][K]) {
  i128 groups[3 * K + 1] = {};
  int perm[K + 1];
  for (int i = 0; i <= K; ++i) perm[i] = i;
  do {
    int inversions = 0;
    for (int i = 0; i <= K; ++i)
      for (int j = i + 1; j <= K; ++j) inversions += perm[i] > perm[j];
    i128 prod = (inversions % 2) ? -1 : 1;
    int g = 0;
    for (int r = 0; r <= K; ++r) {
      if (perm[r] == K) continue;
      prod *= rows[r][perm[r]].v;
      g += rows[r][perm[r]].g;
    }
    groups[g] += prod;
  } while (std::next_permutation(perm, perm + K + 1));
  for (int g = 3 * K; g >= 0; --g)
    if (groups[g] != 0) return sgn(groups[g]);
  return 0;
}

TEST(OrientPredicates, ExtremeExponentRanges) {
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<int> val(-7, 7), grp(0, 2);
  struct Axes {
    int base[3], step[3];
    int bits[3] = {3, 3, 3};  // |v| < 2^bits
  };
  const Axes configs[] = {
      {{-1074, -1074, -1074}, {40, 40, 40}},  // subnormals
      {{-1000, -1000, -1000}, {500, 500, 500}},
      {{-450, -450, -450}, {450, 450, 450}},
      {{0, 0, 0}, {300, 300, 300}},
      {{100, 100, 100}, {450, 450, 450}},
      {{-600, -600, -600}, {600, 600, 600}},
      {{-60, -60, -60}, {30, 30, 30}},
      {{-650, -650, -650}, {325, 325, 325}},  // pairs fine, triple products underflow
      {{-450, -450, 0}, {450, 450, 0}},  // two wide axes, one narrow
      {{-1000, 0, -1000}, {500, 0, 500}},
      {{-3, -900, -900}, {0, 450, 450}},
      {{-700, -3, -3}, {700, 0, 0}, {40, 3, 3}},  // one very wide axis with full mantissas
      {{-20, -600, -20}, {0, 600, 0}, {3, 40, 3}},
  };
  for (const Axes& cfg : configs) {
    for (int i = 0; i < 20000; ++i) {
      Coded r3[4][3];
      Vec3 p[4];
      for (int r = 0; r < 4; ++r)
        for (int k = 0; k < 3; ++k) {
          const int g = cfg.step[k] ? grp(rng) : 0;
          const std::int64_t half = std::int64_t{1} << (cfg.bits[k] - 1);
          const std::int64_t v =
              cfg.bits[k] == 3 ? val(rng) : std::uniform_int_distribution<std::int64_t>(-half, half)(rng);
          r3[r][k] = {v, g};
          p[r][k] = std::ldexp(static_cast<double>(r3[r][k].v), cfg.base[k] + cfg.step[k] * g);
        }
      const int expected = grouped_sign<3>(r3);
      ASSERT_EQ(orient3d_sign(p[0], p[1], p[2], p[3]), expected) << cfg.base[0] << " " << i;
      ASSERT_EQ(detail::orient3d_sign_bigint(p[0], p[1], p[2], p[3]), expected);

      Coded r2[3][2];
      double q[3][2];
      for (int r = 0; r < 3; ++r)
        for (int k = 0; k < 2; ++k) {
          const int g = cfg.step[k] ? grp(rng) : 0;
          r2[r][k] = {val(rng), g};
          q[r][k] = std::ldexp(static_cast<double>(r2[r][k].v), cfg.base[k] + cfg.step[k] * g);
        }
      ASSERT_EQ(orient2d_sign(q[0][0], q[0][1], q[1][0], q[1][1], q[2][0], q[2][1]),
                grouped_sign<2>(r2));
    }
  }
}

// One axis spanning 1400 bits with full mantissas, the others narrow, arranged so that the
// huge term cancels exactly (rows 0-2 have collinear (y, z), so the cofactor of row 3 is 0)
// and the sign is decided by the tiny x's: scaling that axis into the subnormal range would
// lose their low bits, which the exponent-range check must prevent.
TEST(OrientPredicates, WideAxisWithCancellingHugeTerm) {
  std::mt19937_64 rng(9);
  std::uniform_int_distribution<int> small(-3, 3);
  std::uniform_int_distribution<std::int64_t> mant(-(std::int64_t{1} << 39), std::int64_t{1} << 39);
  int nonzero = 0;
  for (int i = 0; i < 20000; ++i) {
    Coded r[4][3];
    const int y0 = small(rng), z0 = small(rng), dy = small(rng), dz = small(rng);
    for (int k = 0; k < 3; ++k) r[k][0] = {mant(rng), 0};  // x = v 2^-700
    r[3][0] = {mant(rng), 1};                               // x = v 2^700
    for (int k = 0; k < 3; ++k) {
      const int t = small(rng);
      r[k][1] = {y0 + t * dy, 0};
      r[k][2] = {z0 + t * dz, 0};
    }
    r[3][1] = {small(rng), 0};
    r[3][2] = {small(rng), 0};
    Vec3 p[4];
    for (int k = 0; k < 4; ++k)
      p[k] = Vec3(std::ldexp(static_cast<double>(r[k][0].v), r[k][0].g ? 700 : -700),
                  static_cast<double>(r[k][1].v), static_cast<double>(r[k][2].v));
    const int expected = grouped_sign<3>(r);
    nonzero += expected != 0;
    ASSERT_EQ(orient3d_sign(p[0], p[1], p[2], p[3]), expected) << i;
  }
  EXPECT_GT(nonzero, 5000);
}

// Points exactly on the plane z = x + y with wildly different magnitudes (x = m 2^e with a
// 26-bit m, y within 2^25 of x's scale, so x + y is exact): the differences are inexact
// (two-component expansions), so a zero needs every low-order term to cancel exactly. Then
// d moved by one ulp along z: orient3d = -step * n_z, n_z = orient2d of the xy projections.
TEST(OrientPredicates, MixedMagnitudeExactPlane) {
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<std::int64_t> mant(-(1 << 26), 1 << 26);
  std::uniform_int_distribution<int> near(-25, 0);
  int span = 70;  // exponents in [-span, span] (+-span only when 330): 70 stays in the
                  // expansion stage, 330 needs the big integer
  auto point = [&] {
    const int e = span < 330 ? std::uniform_int_distribution<int>(-span, span)(rng)
                             : (rng() % 2 ? span : -span);  // extremes only
    const double x = std::ldexp(static_cast<double>(mant(rng)), e);
    const double y = std::ldexp(static_cast<double>(mant(rng)), e + near(rng));
    return Vec3(x, y, x + y);  // exact: at most 26 + 25 + 1 bits
  };
  int nonzero = 0;
  for (int i = 0; i < 45000; ++i) {
    span = i < 30000 ? 70 : (i < 37500 ? 200 : 330);
    const Vec3 a = point(), b = point(), c = point(), d = point();
    ASSERT_EQ(orient3d_sign(a, b, c, d), 0) << i;
    ASSERT_EQ(detail::orient3d_sign_exact(a, b, c, d), 0) << i;
    ASSERT_EQ(detail::orient3d_sign_bigint(a, b, c, d), 0) << i;
    const int nz = detail::orient2d_sign_bigint(a[0], a[1], b[0], b[1], c[0], c[1]);
    ASSERT_EQ(orient2d_sign(a[0], a[1], b[0], b[1], c[0], c[1]), nz);
    for (int dir : {-1, 1}) {
      Vec3 moved = d;
      moved[2] = std::nextafter(d[2], dir > 0 ? INFINITY : -INFINITY);
      ASSERT_EQ(orient3d_sign(a, b, c, moved), -dir * nz) << i;
      ASSERT_EQ(detail::orient3d_sign_bigint(a, b, c, moved), -dir * nz) << i;
      nonzero += nz != 0;
    }
    // The same in 2-D: points of the line v = 2u with mixed magnitudes, then c moved by an
    // ulp along v: orient2d = step * (bx - ax).
    ASSERT_EQ(orient2d_sign(a[0], 2 * a[0], b[0], 2 * b[0], c[0], 2 * c[0]), 0) << i;
    for (int dir : {-1, 1}) {
      const double cv = std::nextafter(2 * c[0], dir > 0 ? INFINITY : -INFINITY);
      ASSERT_EQ(orient2d_sign(a[0], 2 * a[0], b[0], 2 * b[0], c[0], cv),
                dir * ((b[0] > a[0]) - (b[0] < a[0])))
          << i;
    }
  }
  EXPECT_GT(nonzero, 80000);
}

// The adaptive and expansion stages against the big-integer stage: independent exact methods
// on near-degenerate, non-integer inputs (rounded points of a plane, random exponents).
TEST(OrientPredicates, ExactStagesAgreeWithBigInteger) {
  std::mt19937_64 rng(6);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  std::uniform_int_distribution<int> expo(-60, 60);
  for (int i = 0; i < 60000; ++i) {
    const double scale = std::ldexp(1.0, expo(rng));
    const Vec3 off(u() * 1e8 * (i % 3 == 0), u() * 1e3, -u() * 1e5 * (i % 2));
    const Vec3 a = off + scale * Vec3(u(), u(), u());
    const Vec3 b = off + scale * Vec3(u(), u(), u());
    const Vec3 c = off + scale * Vec3(u(), u(), u());
    const double s = u() * 4 - 2, t = u() * 4 - 2;
    const Vec3 d = a + s * (b - a) + t * (c - a);  // on the plane up to rounding
    const int big = detail::orient3d_sign_bigint(a, b, c, d);
    ASSERT_EQ(detail::orient3d_sign_exact(a, b, c, d), big) << i;
    ASSERT_EQ(orient3d_sign(a, b, c, d), big) << i;
    const double ex = a[0] + s * (b[0] - a[0]), ey = a[1] + s * (b[1] - a[1]);
    const int big2 = detail::orient2d_sign_bigint(a[0], a[1], b[0], b[1], ex, ey);
    ASSERT_EQ(detail::orient2d_sign_exact(a[0], a[1], b[0], b[1], ex, ey), big2);
    ASSERT_EQ(orient2d_sign(a[0], a[1], b[0], b[1], ex, ey), big2);
  }
}

// The filter must never decide wrongly: random points, general and near-degenerate.
TEST(OrientPredicates, FilterNeverDisagreesWithExact) {
  std::mt19937_64 rng(7);
  auto u = [&] { return static_cast<double>(rng() >> 11) * 0x1.0p-53; };
  for (int i = 0; i < 200000; ++i) {
    const Vec3 a(u(), u(), u()), b(u(), u(), u()), c(u(), u(), u());
    Vec3 d(u(), u(), u());
    if (i % 2) d = a + u() * (b - a) + u() * (c - a);
    ASSERT_EQ(orient3d_sign(a, b, c, d), detail::orient3d_sign_bigint(a, b, c, d));
    ASSERT_EQ(orient2d_sign(a[0], a[1], b[0], b[1], d[0], d[1]),
              detail::orient2d_sign_bigint(a[0], a[1], b[0], b[1], d[0], d[1]));
  }
}

TEST(OrientPredicates, HugeInputsDoNotOverflow) {
  const double big = 1.7e308;  // differences and products overflow in the filter
  const Vec3 a(-big, -big, 0), b(big, -big, 0), c(-big, big, 0);
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(0, 0, -big)), 1);
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(0, 0, 0x1p-1074)), -1);
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(big, big, 0)), 0);
  EXPECT_EQ(orient2d_sign(-big, -big, big, -big, 0, 0x1p-1074), 1);
  EXPECT_EQ(orient2d_sign(-big, -big, big, big, 0x1p-1074, 0), -1);
}

TEST(OrientPredicates, ExactPathIsCounted) {
  const std::uint64_t before = orient_exact_path_count();
  const Vec3 a(0.1, 0.2, 0.3), b(0.7, 0.1, 0.9), c(0.3, 0.8, 0.2);
  EXPECT_EQ(orient3d_sign(a, b, c, Vec3(0.5, 0.5, 5.0)), orient3d_sign(a, b, c, Vec3(0.5, 0.5, 5.0)));
  EXPECT_EQ(orient_exact_path_count(), before);  // clear-cut: filtered
  EXPECT_EQ(orient3d_sign(a, b, c, b), 0);
  EXPECT_GT(orient_exact_path_count(), before);  // degenerate: exact path
}

}  // namespace
}  // namespace tecido
