// The tritri suite's families (comparisons/suites/tritri/families.*) produce what they claim,
// judged by independent means: exact orientation signs (core/geometry/orient_predicates.h) for
// the exact constructions, CGAL's exact referee for "touches", plain geometry for the rest.
#include "comparisons/suites/tritri/families.h"

#include "comparisons/engines/tri_tri_engines.h"
#include "core/geometry/orient_predicates.h"

#include <gtest/gtest.h>

#include <cstring>
#include <set>

namespace tecido::suites::tritri {
namespace {

constexpr std::uint64_t kSeed = 77;
constexpr long kPairs = 300;

/// Pairs 0..kPairs-1 of the family named `name`.
std::vector<io::TriPair> pairs_of(const std::string& name) {
  const auto& fams = families();
  for (std::size_t f = 0; f < fams.size(); ++f) {
    if (fams[f].name != name) continue;
    std::vector<io::TriPair> out;
    for (long k = 0; k < kPairs; ++k) out.push_back(family_pair(kSeed, f, fams[f], k));
    return out;
  }
  ADD_FAILURE() << "no family " << name;
  return {};
}

/// The CGAL referee, or nullptr in a build without the reference adapters.
const TriTriEngine* referee() { return find_tri_tri_engine("exact"); }

bool same_bits(const Vec3& a, const Vec3& b) { return std::memcmp(a.data(), b.data(), 3 * sizeof(double)) == 0; }

TEST(TritriFamilies, TableListsEveryFamilyOnceRandomFirst) {
  const auto& fams = families();
  ASSERT_EQ(fams.size(), 8u);
  EXPECT_EQ(fams[0].name, "random");
  EXPECT_TRUE(fams[0].random);
  std::set<std::string> names;
  for (std::size_t f = 0; f < fams.size(); ++f) {
    EXPECT_TRUE(names.insert(fams[f].name).second) << fams[f].name;
    EXPECT_EQ(fams[f].random, f == 0);
    EXPECT_FALSE(fams[f].about.empty());
  }
}

TEST(TritriFamilies, APairDependsOnSeedFamilyAndIndexOnly) {
  const auto& fams = families();
  for (std::size_t f = 0; f < fams.size(); ++f) {
    const io::TriPair p = family_pair(kSeed, f, fams[f], 41);
    const io::TriPair again = family_pair(kSeed, f, fams[f], 41);
    EXPECT_EQ(p.id, fams[f].name + "/41");
    for (int i = 0; i < 3; ++i) EXPECT_TRUE(same_bits(p.a[i], again.a[i]) && same_bits(p.b[i], again.b[i]));
    const io::TriPair next = family_pair(kSeed, f, fams[f], 42), other = family_pair(kSeed + 1, f, fams[f], 41);
    EXPECT_FALSE(same_bits(p.a[1], next.a[1]) && same_bits(p.b[2], next.b[2])) << fams[f].name;
    EXPECT_FALSE(same_bits(p.a[1], other.a[1]) && same_bits(p.b[2], other.b[2])) << fams[f].name;
  }
}

TEST(TritriFamilies, RandomPairsLieInTheUnitCube) {
  for (const auto& p : pairs_of("random"))
    for (const Triangle* t : {&p.a, &p.b})
      for (const Vec3& q : *t) EXPECT_TRUE(q.minCoeff() >= 0.0 && q.maxCoeff() < 1.0) << p.id;
}

TEST(TritriFamilies, CoplanarPairsAreExactlyCoplanar) {
  for (const auto& p : pairs_of("coplanar")) {
    const Vec3 pts[6] = {p.a[0], p.a[1], p.a[2], p.b[0], p.b[1], p.b[2]};
    for (int i = 0; i < 6; ++i)
      for (int j = i + 1; j < 6; ++j)
        for (int k = j + 1; k < 6; ++k)
          for (int l = k + 1; l < 6; ++l) ASSERT_EQ(orient3d_sign(pts[i], pts[j], pts[k], pts[l]), 0) << p.id;
  }
}

TEST(TritriFamilies, NearCoplanarPairsAreWithinAMicronOfTheFirstPlane) {
  int off_plane = 0;
  for (const auto& p : pairs_of("near-coplanar")) {
    const Vec3 n = (p.a[1] - p.a[0]).cross(p.a[2] - p.a[0]).normalized();
    for (const Vec3& q : p.b) {
      EXPECT_LE(std::abs(n.dot(q - p.a[0])), 1e-6 + 1e-14) << p.id;
      off_plane += orient3d_sign(p.a[0], p.a[1], p.a[2], q) != 0;
    }
  }
  EXPECT_GT(off_plane, 0) << "near, not on";
}

TEST(TritriFamilies, TouchVertexPairsTouchAtAVertexOfB) {
  for (const auto& p : pairs_of("touch-vertex")) {
    ASSERT_EQ(orient3d_sign(p.a[0], p.a[1], p.a[2], p.b[0]), 0) << p.id << ": b's first vertex is in a's plane";
    if (!referee()) continue;
    const Triangle point{p.b[0], p.b[0], p.b[0]};
    EXPECT_EQ(referee()->test(p.a, point), true) << p.id << ": the vertex lies on a's closed face";
    EXPECT_EQ(referee()->test(p.a, p.b), true) << p.id;
  }
  if (!referee()) GTEST_SKIP() << "no exact referee in this build; plane membership checked only";
}

TEST(TritriFamilies, TouchEdgePairsMeetAtTheMidpointOfAnEdgeOfA) {
  for (const auto& p : pairs_of("touch-edge")) {
    const Vec3 mid_b = 0.5 * (p.b[0] + p.b[1]);
    bool on_edge_of_a = false;
    for (int e = 0; e < 3; ++e) on_edge_of_a = on_edge_of_a || same_bits(mid_b, 0.5 * (p.a[e] + p.a[(e + 1) % 3]));
    EXPECT_TRUE(on_edge_of_a) << p.id;
    if (referee()) {
      EXPECT_EQ(referee()->test(p.a, p.b), true) << p.id;
    }
  }
}

TEST(TritriFamilies, SharedVertexPairsShareAVertex) {
  for (const auto& p : pairs_of("shared-vertex")) {
    EXPECT_TRUE(same_bits(p.b[0], p.a[0]) || same_bits(p.b[0], p.a[1]) || same_bits(p.b[0], p.a[2])) << p.id;
    if (referee()) {
      EXPECT_EQ(referee()->test(p.a, p.b), true) << p.id;
    }
  }
}

TEST(TritriFamilies, SliversAreWithinTenMicronsOfALine) {
  int exactly_collinear = 0;
  for (const auto& p : pairs_of("sliver")) {
    const Vec3 d = (p.a[1] - p.a[0]).normalized();
    const Vec3 off = (p.a[2] - p.a[0]) - d.dot(p.a[2] - p.a[0]) * d;
    EXPECT_LE(off.norm(), 1e-5 + 1e-14) << p.id;
    exactly_collinear += off.norm() < 1e-15;
  }
  EXPECT_GT(exactly_collinear, 0);
}

TEST(TritriFamilies, OffsetPairsAreUnitSizedAndFarFromTheOrigin) {
  for (const auto& p : pairs_of("offset")) {
    Vec3 lo = p.a[0], hi = p.a[0];
    for (const Triangle* t : {&p.a, &p.b})
      for (const Vec3& q : *t) lo = lo.cwiseMin(q), hi = hi.cwiseMax(q);
    EXPECT_LE((hi - lo).maxCoeff(), 1.0 + 1e-15 * hi.norm()) << p.id;  // a unit box, up to rounding at the offset
    EXPECT_GE(lo.norm(), 1e3 - 2.0) << p.id;
    EXPECT_LE(hi.norm(), 1e8 + 2.0) << p.id;
  }
}

}  // namespace
}  // namespace tecido::suites::tritri
