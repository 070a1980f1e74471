// The ccd suite's families (comparisons/suites/ccd/families.h): each constructed answer against
// the exact referee, the exact transformations against the referee, determinism; and core's
// property on every family: no missed contact, never a time after the referee's.
#include "comparisons/engines/ccd_engines.h"
#include "comparisons/suites/ccd/families.h"
#include "reference/exact_ccd.h"

#include <gtest/gtest.h>

#include <cstring>

namespace tecido::suites::ccd {
namespace {

Settings small(std::size_t n) {
  Settings s = settings(true);
  s.per_family = s.random_per_family = n;
  return s;
}

bool same_bits(const CcdQuery& a, const CcdQuery& b) {
  return a.kind == b.kind && std::memcmp(a.x0.data(), b.x0.data(), sizeof a.x0) == 0 &&
         std::memcmp(a.x1.data(), b.x1.data(), sizeof a.x1) == 0;
}

TEST(CcdFamilies, EveryFamilyIsDeterministicAndSeeded) {
  const Settings s = small(50);
  for (std::size_t k = 0; k < families().size(); ++k) {
    const auto a = family_queries(k, s, 3), b = family_queries(k, s, 3), c = family_queries(k, s, 4);
    ASSERT_EQ(a.size(), 50u) << family_name(families()[k]);
    bool all_same = true, any_differs = false;
    for (std::size_t i = 0; i < a.size(); ++i) {
      all_same = all_same && same_bits(a[i].q, b[i].q) && a[i].known == b[i].known && a[i].toi == b[i].toi;
      any_differs = any_differs || !same_bits(a[i].q, c[i].q);
      EXPECT_EQ(a[i].q.kind, families()[k].kind);
      EXPECT_EQ(a[i].known >= 0, families()[k].constructed) << family_name(families()[k]) << " " << i;
    }
    EXPECT_TRUE(all_same) << family_name(families()[k]);
    EXPECT_TRUE(any_differs) << family_name(families()[k]);
  }
}

TEST(CcdFamilies, ConstructedFamiliesHaveBothAnswers) {
  // A family of hits only (or misses only) could not show a false positive (or negative);
  // parallel motion is the one family of misses by design.
  const Settings s = small(200);
  for (std::size_t k = 0; k < families().size(); ++k) {
    const Family& f = families()[k];
    if (!f.constructed) continue;
    int hits = 0;
    for (const KnownQuery& kq : family_queries(k, s, 9)) hits += kq.known == 1;
    if (std::string(f.name) == "parallel") {
      EXPECT_EQ(hits, 0) << family_name(f);
    } else {
      EXPECT_GT(hits, 20) << family_name(f);
      EXPECT_LT(hits, 190) << family_name(f);
    }
  }
}

TEST(CcdFamilies, TheRefereeReproducesEveryConstructedAnswer) {
  const Settings s = small(300);
  for (std::size_t k = 0; k < families().size(); ++k) {
    if (!families()[k].constructed) continue;
    int wrong = 0;
    for (const KnownQuery& kq : family_queries(k, s, 21)) {
      const reference::ExactCcd e = reference::exact_ccd(kq.q);
      const bool ok = e.hit == (kq.known == 1) && (!e.hit || (e.toi_exact && e.toi == kq.toi));
      wrong += !ok;
    }
    EXPECT_EQ(wrong, 0) << family_name(families()[k]);
  }
}

TEST(CcdConstructions, ExactTransformationsKeepTheRefereesAnswer) {
  // Generic crossings, then each transformation: the referee's hit and toi must not change.
  Rng r(5);
  const Settings s = small(100);
  for (std::size_t k : {std::size_t{1}, std::size_t{10}}) {  // vertex-face/crossing, edge-edge/crossing
    for (const KnownQuery& kq : family_queries(k, s, 77)) {
      const reference::ExactCcd e = reference::exact_ccd(kq.q);
      for (const CcdQuery& t : {mapped(kq.q, random_affine(r)), permuted_axes(kq.q, r), relabelled(kq.q, r),
                                scaled(kq.q, -700), scaled(kq.q, 700), translated(kq.q, Vec3(0x1p30, -0x1p30, 0x1p20))}) {
        const reference::ExactCcd f = reference::exact_ccd(t);
        ASSERT_EQ(f.hit, e.hit);
        if (e.hit) {
          EXPECT_EQ(f.toi, e.toi);
        }
      }
    }
  }
}

TEST(CcdFamilies, CoreNeverMissesAndIsNeverLate) {
  // Core's zero-false-negative property (core/geometry/ccd/ccd.h) on every family, adversarial ones
  // included, against the exact referee; its toi is never after the first contact.
  const CcdEngine* core = find_ccd_engine("core");
  ASSERT_NE(core, nullptr);
  const Settings s = small(400);
  for (std::size_t k = 0; k < families().size(); ++k) {
    int missed = 0, late = 0;
    for (const KnownQuery& kq : family_queries(k, s, 1234)) {
      const reference::ExactCcd e = reference::exact_ccd(kq.q);
      const CcdAnswer a = *core->test(kq.q);
      missed += e.hit && !a.hit;
      late += e.hit && a.hit && a.toi > (e.toi_exact ? e.toi : e.toi_lo);
    }
    EXPECT_EQ(missed, 0) << family_name(families()[k]);
    EXPECT_EQ(late, 0) << family_name(families()[k]);
  }
}

}  // namespace
}  // namespace tecido::suites::ccd
