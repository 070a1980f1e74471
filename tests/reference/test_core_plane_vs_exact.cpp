// Core's segment-versus-bounded-plane decision against the exact referee (CGAL/GMP rationals)
// on adversarial cases built the way the plane suite builds them (comparisons/suites/
// plane_suite.cpp): crossings on an edge or a corner up to one rounding, the same nudged by one
// or two ulps, grazing segments, random cases, and exact geometry on axis-aligned planes
// (parallel, in the plane, starting or ending on it), each at scales from 1e-300 to 1e300 and
// offset far from the origin. core.hit must equal the referee's hit on every case.
#include "core/geometry/segment_plane.h"
#include "reference/exact_referee.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace tecido {
namespace {

struct Case {
  BoundedPlane plane;
  Vec3 from, to;
};

class Gen {
 public:
  explicit Gen(std::uint64_t seed) : g_(seed) {}
  double unit() { return static_cast<double>(g_() >> 11) * 0x1.0p-53; }
  double uniform(double a, double b) { return a + (b - a) * unit(); }
  int below(int n) { return static_cast<int>(g_() % static_cast<std::uint64_t>(n)); }
  double sign() { return below(2) ? 1.0 : -1.0; }
  Vec3 in_box(double lo, double hi) { return Vec3(uniform(lo, hi), uniform(lo, hi), uniform(lo, hi)); }
  Vec3 unit_vector() {
    for (;;) {
      const Vec3 v = in_box(-1.0, 1.0);
      const double n = v.norm();
      if (n > 1e-3 && n <= 1.0) return v / n;
    }
  }
  /// x moved by 0, 1 or 2 ulps up or down.
  double nudge(double x) {
    const int k = below(3);
    const double dir = below(2) ? INFINITY : -INFINITY;
    for (int i = 0; i < k; ++i) x = std::nextafter(x, dir);
    return x;
  }
  Vec3 nudge(const Vec3& v) { return Vec3(nudge(v.x()), nudge(v.y()), nudge(v.z())); }

 private:
  std::mt19937_64 g_;
};

/// A random plane of the suite's kind, centred at `centre`, half extents in [0.1, 2] * scale.
BoundedPlane random_plane(Gen& r, const Vec3& centre, double scale) {
  const Vec3 n = r.unit_vector();
  Vec3 f = r.unit_vector();
  while (n.cross(f).norm() < 0.1) f = r.unit_vector();
  return make_bounded_plane(centre, n, f, Vec2(r.uniform(0.1, 2.0), r.uniform(0.1, 2.0)) * scale, 0.0);
}

/// A segment through c along a direction not parallel to the plane, lengths ~ scale.
Case through(Gen& r, const BoundedPlane& p, const Vec3& c, double scale) {
  Vec3 d = r.unit_vector();
  if (std::abs(d.dot(p.normal)) < 0.2) d += p.normal;
  const double a = r.uniform(0.05, 1.5) * scale, b = r.uniform(0.05, 1.5) * scale;
  return {p, c - a * d, c + b * d};
}

/// One case of `category` at `scale` (every length multiplied by it) and offset `shift`.
Case make_case(Gen& r, const std::string& category, double scale, const Vec3& shift) {
  const BoundedPlane p = random_plane(r, shift + r.in_box(-1, 1) * scale, scale);
  const double hx = p.half_extents.x(), hy = p.half_extents.y();
  if (category == "edge" || category == "edge-nudged") {
    const Vec3 c = r.below(2) ? p.position + r.sign() * hx * p.forward + r.uniform(-1, 1) * hy * p.right()
                              : p.position + r.uniform(-1, 1) * hx * p.forward + r.sign() * hy * p.right();
    Case k = through(r, p, c, scale);
    if (category == "edge-nudged") k = {p, r.nudge(k.from), r.nudge(k.to)};
    return k;
  }
  if (category == "corner" || category == "corner-nudged") {
    const Vec3 c = p.position + r.sign() * hx * p.forward + r.sign() * hy * p.right();
    Case k = through(r, p, c, scale);
    if (category == "corner-nudged") k = {p, r.nudge(k.from), r.nudge(k.to)};
    return k;
  }
  if (category == "grazing") {
    const Vec3 c = p.position + r.uniform(-1.2, 1.2) * hx * p.forward + r.uniform(-1.2, 1.2) * hy * p.right();
    const Vec3 t = (r.uniform(-1, 1) * p.forward + r.uniform(-1, 1) * p.right()).normalized();
    const Vec3 d = (t + std::pow(10.0, r.uniform(-12, -3)) * r.sign() * p.normal).normalized();
    return {p, c - r.uniform(0.1, 1.0) * scale * d, c + r.uniform(0.1, 1.0) * scale * d};
  }
  if (category == "start-on-tilted") {  // an end point on a tilted plane up to one rounding
    const Vec3 c = p.position + r.uniform(-1.2, 1.2) * hx * p.forward + r.uniform(-1.2, 1.2) * hy * p.right();
    return {p, r.nudge(c), c + r.uniform(-1, 1) * scale * p.normal + r.in_box(-1, 1) * scale};
  }
  return {p, shift + r.in_box(-2.5, 2.5) * scale, shift + r.in_box(-2.5, 2.5) * scale};  // random
}

/// Exact geometry on an axis-aligned plane at a dyadic height (the suite's flat_plane, scaled
/// by a power of two so that it stays exact): parallel, in the plane, starting or ending on it.
Case exact_geometry_case(Gen& r, int kind, int e) {
  const double s = std::ldexp(1.0, e);
  const double z = std::ldexp(static_cast<double>(r.below(64)) - 32.0, -3) * s;
  const Vec3 f = r.below(2) ? Vec3(1, 0, 0) : Vec3(0, 1, 0);
  const BoundedPlane p = make_bounded_plane(Vec3(std::ldexp(static_cast<double>(r.below(16)), -2) * s, 0.5 * s, z),
                                            Vec3(0, 0, 1), f,
                                            Vec2(std::ldexp(1.0 + r.below(8), -2), std::ldexp(1.0 + r.below(8), -2)) * s, 0.0);
  auto grid = [&](double lo, double hi) {  // a dyadic coordinate, often exactly on the border
    return std::ldexp(std::round(r.uniform(lo, hi) * 8.0), -3) * s;
  };
  const Vec3 on(grid(-2, 3), grid(-1.5, 2.5), z);
  switch (kind) {
    case 0: {  // parallel, 1 down to 2^-39 above or below
      const double dz = std::ldexp(1.0, -r.below(40)) * s * r.sign();
      return {p, Vec3(grid(-3, 3), grid(-3, 3), z + dz), Vec3(grid(-3, 3), grid(-3, 3), z + dz)};
    }
    case 1:  // in the plane
      return {p, on, Vec3(grid(-2, 3), grid(-1.5, 2.5), z)};
    default: {  // starting (2) or ending (3) on the plane
      const Vec3 off = on + Vec3(grid(-1, 1), grid(-1, 1), std::ldexp(1.0 + r.below(8), -3) * s * r.sign());
      return kind == 2 ? Case{p, on, off} : Case{p, off, on};
    }
  }
}

struct Tally {
  long cases = 0, hits = 0, exact_path = 0;
};

void check(const Case& c, const std::string& label, Tally& t) {
  const std::uint64_t before = segment_plane_exact_path_count();
  const SegmentPlaneHit core = segment_plane(c.plane, c.from, c.to);
  t.exact_path += segment_plane_exact_path_count() != before;
  const reference::ExactSegmentPlane ref = reference::exact_segment_plane(c.plane, c.from, c.to);
  ++t.cases;
  t.hits += ref.hit;
  ASSERT_EQ(core.hit, ref.hit) << label << std::hexfloat << "\n P=" << c.plane.position.transpose()
                               << "\n n=" << c.plane.normal.transpose() << "\n f=" << c.plane.forward.transpose()
                               << "\n h=" << c.plane.half_extents.transpose() << "\n p1=" << c.from.transpose()
                               << "\n p2=" << c.to.transpose();
  if (core.hit) {
    ASSERT_GE(core.t, 0.0) << label;
    ASSERT_LE(core.t, 1.0) << label;
  }
}

TEST(CorePlaneVsExact, AdversarialRandomAndExactGeometryCasesAcrossScales) {
  const double scales[] = {1.0, 1e-300, 1e-150, 1e-40, 1e-8, 1e8, 1e40, 1e150, 1e300};
  const char* categories[] = {"edge", "edge-nudged", "corner", "corner-nudged", "grazing", "start-on-tilted", "random"};
  const int per_category = 1500;
  Tally border, all;
  std::uint64_t seed = 1;
  for (const double scale : scales) {
    for (const char* cat : categories) {
      const std::string category = cat;
      for (int k = 0; k < per_category; ++k) {
        Gen r(seed++);
        // Every third case far from the origin (1e3..1e8 times the scale, at most 1e306), as the
        // suite's "far" category.
        const double far = k % 3 == 2 ? std::min(std::pow(10.0, 3 + k % 6) * scale, 1e306) : 0.0;
        const Vec3 shift = far * r.unit_vector();
        const Case c = make_case(r, category, scale, shift);
        Tally& t = category.rfind("edge", 0) == 0 || category.rfind("corner", 0) == 0 ? border : all;
        check(c, category + " scale " + std::to_string(scale) + " #" + std::to_string(k), t);
        if (HasFatalFailure()) return;
      }
    }
  }
  for (const int e : {0, -1000, -500, -100, 100, 500, 1000}) {
    for (int kind = 0; kind < 4; ++kind) {
      for (int k = 0; k < 1000; ++k) {
        Gen r(seed++);
        check(exact_geometry_case(r, kind, e), "exact geometry kind " + std::to_string(kind) + " scale 2^" + std::to_string(e), all);
        if (HasFatalFailure()) return;
      }
    }
  }
  // The border cases are adversarial: many hit, many miss, and many are beyond the filter.
  EXPECT_GE(border.cases + all.cases, 100000);
  EXPECT_GT(border.hits, border.cases / 5);
  EXPECT_LT(border.hits, border.cases * 4 / 5);
  EXPECT_GT(border.exact_path, border.cases / 4);
}

}  // namespace
}  // namespace tecido
