// The plane suite's categories (comparisons/suites/plane/categories.*) produce what they claim,
// judged by independent means: the exact referee (CGAL rationals) for where a crossing lies (an
// "edge" case hits when moved 1e-7 m inward across that edge and misses when moved as far
// outward), exact comparisons of coordinates for the axis-aligned constructions, plain geometry for
// the rest.
#include "comparisons/suites/plane/categories.h"

#include "comparisons/engines/segment_plane_engines.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <set>

namespace tecido::suites::plane {
namespace {

constexpr std::uint64_t kSeed = 77;
constexpr long kCases = 300;

std::vector<io::PlaneCase> cases_of(const std::string& name) {
  const auto& cats = categories();
  for (std::size_t c = 0; c < cats.size(); ++c) {
    if (cats[c].name != name) continue;
    std::vector<io::PlaneCase> out;
    for (long k = 0; k < kCases; ++k) out.push_back(category_case(kSeed, c, cats[c], k));
    return out;
  }
  ADD_FAILURE() << "no category " << name;
  return {};
}

/// The CGAL referee, or nullptr in a build without the reference adapters.
const SegmentPlaneEngine* referee() { return find_segment_plane_engine("exact"); }

SegmentPlaneHit judge(const io::PlaneCase& c, const Vec3& shift = Vec3::Zero()) {
  return *referee()->test(c.plane, c.from + shift, c.to + shift);
}

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0; }

/// Coordinates of the segment's crossing with the plane, in the rectangle's frame (floating point).
Vec2 crossing_uv(const io::PlaneCase& c) {
  const BoundedPlane& p = c.plane;
  const double s1 = p.normal.dot(c.from - p.position), s2 = p.normal.dot(c.to - p.position);
  const Vec3 cp = c.from + s1 / (s1 - s2) * (c.to - c.from) - p.position;
  return Vec2(p.forward.dot(cp), p.right().dot(cp));
}

TEST(PlaneCategories, TableListsEveryCategoryOnceRandomFirst) {
  const auto& cats = categories();
  ASSERT_EQ(cats.size(), 9u);
  std::set<std::string> names;
  for (std::size_t c = 0; c < cats.size(); ++c) {
    EXPECT_TRUE(names.insert(cats[c].name).second) << cats[c].name;
    EXPECT_EQ(cats[c].random, c == 0) << cats[c].name;
    EXPECT_FALSE(cats[c].about.empty());
  }
  EXPECT_EQ(cats[0].name, "random");
}

TEST(PlaneCategories, ACaseDependsOnSeedCategoryAndIndexOnly) {
  const auto& cats = categories();
  for (std::size_t c = 0; c < cats.size(); ++c) {
    const io::PlaneCase a = category_case(kSeed, c, cats[c], 41), again = category_case(kSeed, c, cats[c], 41);
    EXPECT_EQ(a.id, cats[c].name + "/41");
    EXPECT_EQ(case_category(a.id), cats[c].name);
    EXPECT_TRUE(same_bits(a.from, again.from) && same_bits(a.to, again.to) && same_bits(a.plane.normal, again.plane.normal));
    const io::PlaneCase next = category_case(kSeed, c, cats[c], 42), other = category_case(kSeed + 1, c, cats[c], 41);
    EXPECT_FALSE(same_bits(a.from, next.from)) << cats[c].name;
    EXPECT_FALSE(same_bits(a.from, other.from)) << cats[c].name;
  }
}

TEST(PlaneCategories, RandomCasesLieInTheirBoxesAndBothHitAndMiss) {
  int hits = 0;
  for (const auto& c : cases_of("random")) {
    EXPECT_LE(c.from.cwiseAbs().maxCoeff(), 2.5);
    EXPECT_LE(c.to.cwiseAbs().maxCoeff(), 2.5);
    EXPECT_LE(c.plane.position.cwiseAbs().maxCoeff(), 0.5);
    EXPECT_GE(c.plane.half_extents.minCoeff(), 0.1);
    EXPECT_LE(c.plane.half_extents.maxCoeff(), 2.0);
    if (referee()) hits += judge(c).hit;
  }
  if (!referee()) GTEST_SKIP() << "no exact referee in this build";
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, kCases);
}

/// Moves the segment by `delta` along the in-plane direction `dir` (a unit vector of the plane).
SegmentPlaneHit moved(const io::PlaneCase& c, const Vec3& dir, double delta) { return judge(c, delta * dir); }

TEST(PlaneCategories, EdgeCasesCrossOnAnEdgePerTheReferee) {
  if (!referee()) GTEST_SKIP() << "no exact referee in this build";
  const double delta = 1e-7;
  int hits = 0;
  for (const auto& c : cases_of("edge")) {
    const Vec2 uv = crossing_uv(c);
    const Vec2 h = c.plane.half_extents;
    // The edge is the side whose coordinate is at the half extent; the other coordinate is inside.
    const bool on_x = std::abs(std::abs(uv.x()) - h.x()) < std::abs(std::abs(uv.y()) - h.y());
    const Vec3 out = on_x ? (uv.x() > 0 ? 1.0 : -1.0) * c.plane.forward : (uv.y() > 0 ? 1.0 : -1.0) * c.plane.right();
    EXPECT_LT(on_x ? std::abs(std::abs(uv.x()) - h.x()) : std::abs(std::abs(uv.y()) - h.y()), 1e-12) << c.id;
    EXPECT_FALSE(moved(c, out, delta).hit) << c.id << ": still hits 1e-7 m outside the edge";
    EXPECT_TRUE(moved(c, out, -delta).hit) << c.id << ": misses 1e-7 m inside the edge";
    hits += judge(c).hit;
  }
  // On the edge up to one rounding: the referee says hit for some, miss for others.
  EXPECT_GT(hits, kCases / 10);
  EXPECT_LT(hits, kCases * 9 / 10);
}

TEST(PlaneCategories, CornerCasesCrossAtACornerPerTheReferee) {
  if (!referee()) GTEST_SKIP() << "no exact referee in this build";
  const double delta = 1e-7;
  int hits = 0;
  for (const auto& c : cases_of("corner")) {
    const Vec2 uv = crossing_uv(c);
    EXPECT_LT(std::abs(std::abs(uv.x()) - c.plane.half_extents.x()), 1e-12) << c.id;
    EXPECT_LT(std::abs(std::abs(uv.y()) - c.plane.half_extents.y()), 1e-12) << c.id;
    const Vec3 fx = (uv.x() > 0 ? 1.0 : -1.0) * c.plane.forward, fy = (uv.y() > 0 ? 1.0 : -1.0) * c.plane.right();
    EXPECT_FALSE(moved(c, fx, delta).hit) << c.id;
    EXPECT_FALSE(moved(c, fy, delta).hit) << c.id;
    EXPECT_TRUE(moved(c, (fx + fy).normalized(), -delta).hit) << c.id;
    hits += judge(c).hit;
  }
  EXPECT_GT(hits, kCases / 10);
  EXPECT_LT(hits, kCases * 9 / 10);
}

TEST(PlaneCategories, EdgeAndCornerSegmentsCrossSteeply) {
  for (const char* name : {"edge", "corner"})
    for (const auto& c : cases_of(name)) {
      const Vec3 d = c.to - c.from;
      EXPECT_GE(std::abs(d.dot(c.plane.normal)) / d.norm(), 0.2 - 1e-12) << c.id;
    }
}

TEST(PlaneCategories, GrazingCasesAreGrazing) {
  int hits = 0;
  double smallest = 1.0;
  for (const auto& c : cases_of("grazing")) {
    const Vec3 d = c.to - c.from;
    const double sine = std::abs(d.dot(c.plane.normal)) / d.norm();
    EXPECT_LE(sine, 1.0001e-3) << c.id;
    smallest = std::min(smallest, sine);
    if (referee()) hits += judge(c).hit;
  }
  EXPECT_LT(smallest, 1e-9);  // the tilt spans 1e-12 .. 1e-3
  if (!referee()) GTEST_SKIP() << "no exact referee in this build";
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, kCases);
}

/// The axis-aligned categories: the plane's normal is exactly +z and forward an exact axis.
void expect_flat(const io::PlaneCase& c) {
  EXPECT_EQ(c.plane.normal, Vec3(0, 0, 1)) << c.id;
  EXPECT_TRUE(c.plane.forward == Vec3(1, 0, 0) || c.plane.forward == Vec3(0, 1, 0)) << c.id;
}

TEST(PlaneCategories, ParallelCasesAreExactlyParallelAndOffThePlane) {
  for (const auto& c : cases_of("parallel")) {
    expect_flat(c);
    EXPECT_EQ(c.from.z(), c.to.z()) << c.id;
    EXPECT_NE(c.from.z(), c.plane.position.z()) << c.id;
    EXPECT_LE(std::abs(c.from.z() - c.plane.position.z()), 1.0) << c.id;
    if (referee()) {
      EXPECT_FALSE(judge(c).hit) << c.id;
    }
  }
}

TEST(PlaneCategories, InPlaneCasesLieExactlyInThePlane) {
  int hits = 0;
  for (const auto& c : cases_of("in-plane")) {
    expect_flat(c);
    EXPECT_EQ(c.from.z(), c.plane.position.z()) << c.id;
    EXPECT_EQ(c.to.z(), c.plane.position.z()) << c.id;
    if (referee()) hits += judge(c).hit;
  }
  if (!referee()) GTEST_SKIP() << "no exact referee in this build";
  EXPECT_GT(hits, 0);
  EXPECT_LT(hits, kCases);
}

/// Whether `p` (on the flat plane) is inside the closed rectangle; nullopt within 1e-12 of its border.
std::optional<bool> inside(const BoundedPlane& plane, const Vec3& p) {
  const Vec3 d = p - plane.position;
  const double u = std::abs(plane.forward.dot(d)), v = std::abs(plane.right().dot(d));
  const double margin = std::min(std::abs(u - plane.half_extents.x()), std::abs(v - plane.half_extents.y()));
  if (margin < 1e-12) return std::nullopt;
  return u <= plane.half_extents.x() && v <= plane.half_extents.y();
}

TEST(PlaneCategories, StartOnAndEndOnCasesHaveThatEndExactlyOnThePlane) {
  for (const char* name : {"start-on", "end-on"}) {
    const bool start = std::string(name) == "start-on";
    int hits = 0;
    for (const auto& c : cases_of(name)) {
      expect_flat(c);
      const Vec3& on = start ? c.from : c.to;
      const Vec3& off = start ? c.to : c.from;
      EXPECT_EQ(on.z(), c.plane.position.z()) << c.id;
      EXPECT_NE(off.z(), c.plane.position.z()) << c.id;
      if (!referee()) continue;
      const SegmentPlaneHit h = judge(c);
      hits += h.hit;
      // The other end is off the plane, so the segment touches it at `on` only: a hit exactly when
      // `on` is inside the rectangle, at t = 0 or 1.
      if (const auto in = inside(c.plane, on)) {
        EXPECT_EQ(h.hit, *in) << c.id;
      }
      if (h.hit) {
        EXPECT_EQ(h.t, start ? 0.0 : 1.0) << c.id;
      }
    }
    if (referee()) {
      EXPECT_GT(hits, 0) << name;
      EXPECT_LT(hits, kCases) << name;
    }
  }
}

TEST(PlaneCategories, FarCasesAreFarFromTheOrigin) {
  const auto cases = cases_of("far");
  for (long k = 0; k < kCases; ++k) {
    const io::PlaneCase& c = cases[k];
    const double offset = std::pow(10.0, 3 + static_cast<double>(k % 6));
    EXPECT_NEAR(c.plane.position.norm(), offset, 1.0) << c.id;
    EXPECT_NEAR(c.from.norm(), offset, 5.0) << c.id;
    EXPECT_LE((c.from - c.plane.position).norm(), 6.0) << c.id;
  }
}

}  // namespace
}  // namespace tecido::suites::plane
