// The certified floating-point filter of the exact CCD referee: whenever it answers, its answer
// is the exact path's (hit, toi and its bracket), on generic, near-contact and degenerate
// queries; it proves the obvious misses; it declines what it cannot prove.
#include "reference/exact_ccd_filter.h"

#include "reference/exact_ccd.h"
#include "tests/reference/ccd_test_cases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

namespace tecido::reference {
namespace {

using ccd_cases::make;
const Vec3 O(0, 0, 0), X(1, 0, 0), Y(0, 1, 0);

using Kind = CcdFilterVerdict::Kind;

/// Checks the filter's verdict against the exact path (a proven hit brackets the exact time
/// and, when it rounds, rounds it the same way); returns whether the filter proved anything.
bool agrees(const CcdQuery& q) {
  const CcdFilterVerdict f = certified_float_ccd(q);
  if (f.kind == Kind::Unproven) return false;
  const ExactCcd e = exact_ccd_unfiltered(q);
  EXPECT_EQ(f.kind == Kind::Hit, e.hit);
  if (f.kind == Kind::Hit && e.hit) {
    EXPECT_FALSE(e.toi_exact);  // the filter never proves a root at a double
    EXPECT_LE(f.lo, e.toi_lo);
    EXPECT_GE(f.hi, e.toi_hi);
    EXPECT_NE(f.sign_lo, 0);
    if (f.toi) {
      EXPECT_EQ(*f.toi, e.toi);
      EXPECT_EQ(f.lo, e.toi_lo);
      EXPECT_EQ(f.hi, e.toi_hi);
    }
  }
  return true;
}

Vec3 random_vec(std::mt19937& rng, double scale) {
  std::uniform_real_distribution<double> d(-scale, scale);
  return Vec3(d(rng), d(rng), d(rng));
}

TEST(ExactCcdFilter, AgreesWithTheExactPathOnGenericQueries) {
  std::mt19937 rng(99);
  int answered = 0, hits = 0;
  for (int i = 0; i < 3000; ++i) {
    CcdQuery q;
    q.kind = i % 2 ? CcdKind::VertexFace : CcdKind::EdgeEdge;
    for (std::size_t k = 0; k < 4; ++k) {
      q.x0[k] = random_vec(rng, 1);
      q.x1[k] = q.x0[k] + random_vec(rng, 0.5);
    }
    SCOPED_TRACE(i);
    if (agrees(q)) {
      ++answered;
      hits += certified_float_ccd(q).kind == Kind::Hit;
    }
  }
  // Generic double inputs have irrational contact times and non-zero signs: the filter proves
  // nearly all of them, hits included.
  EXPECT_GT(answered, 2900);
  EXPECT_GT(hits, 50);
}

// Constructed contacts (inside, on an edge, at an end point) moved off by a few ulps, at scales
// 2^-80 to 2^80: the filter must never answer wrongly, however close the call. It proves about
// half of them: the interior ones, whose contact is not decided by a zero.
TEST(ExactCcdFilter, AgreesOnNearContacts) {
  std::mt19937 rng(5);
  std::uniform_int_distribution<int> ulps(-3, 3);
  int answered = 0;
  for (int i = 0; i < 2000; ++i) {
    const double t = (1 + i % 7) / 8.0;
    const bool edge = i % 4 >= 2;
    ccd_cases::Known k =
        i % 2 ? ccd_cases::vf_translation(
                    rng, t, edge ? std::array<double, 3>{0, 0.5, 0.5} : std::array<double, 3>{0.25, 0.25, 0.5})
              : ccd_cases::ee_translation(rng, t, edge ? 1.0 : 0.25, 0.5);
    const double scale = std::ldexp(1.0, (i % 5 - 2) * 40);
    for (std::size_t j = 0; j < 4; ++j) {
      k.q.x0[j] *= scale;
      k.q.x1[j] *= scale;
      for (int c = 0; c < 3; ++c) {
        const int n = ulps(rng);
        for (int s = 0; s < std::abs(n); ++s) k.q.x1[j][c] = std::nextafter(k.q.x1[j][c], n > 0 ? INFINITY : -INFINITY);
      }
    }
    SCOPED_TRACE(i);
    answered += agrees(k.q);
  }
  EXPECT_GT(answered, 600);
}

TEST(ExactCcdFilter, ProvesSeparatedBoxesAndPlanesMisses) {
  // Swept boxes disjoint in x.
  EXPECT_EQ(certified_float_ccd(make(CcdKind::VertexFace, {Vec3(2, 0, 0), O, X, Y}, {Vec3(3, 1, 1), O, X, Y})).kind,
            Kind::Miss);
  // Overlapping boxes, but the vertex stays above the plane z = 0: the cubic p_z(t) > 0.
  EXPECT_EQ(
      certified_float_ccd(make(CcdKind::VertexFace, {Vec3(0.25, 0.25, 1), O, X, Y}, {Vec3(0.5, 0.25, 0.125), O, X, Y}))
          .kind,
      Kind::Miss);
}

// 1 - 2t^2 = 0 at t = 1/sqrt(2) (test_exact_ccd.cpp works the case): an irrational root with
// non-zero signs everywhere, so the filter proves the hit and brackets it.
TEST(ExactCcdFilter, ProvesAnIrrationalHit) {
  const CcdQuery q = make(CcdKind::VertexFace, {Vec3(0.25, 0, 1), O, X, Y}, {Vec3(0.25, 1, 1), O, X, Vec3(0, 1, 2)});
  ASSERT_TRUE(agrees(q));
  const CcdFilterVerdict f = certified_float_ccd(q);
  EXPECT_EQ(f.kind, Kind::Hit);
  EXPECT_LT(f.lo, std::sqrt(0.5));
  EXPECT_GT(f.hi, std::sqrt(0.5));
  EXPECT_LT(f.hi - f.lo, 1e-12);
}

// What only exact arithmetic can settle is declined: coplanar-throughout motion, a contact
// decided by a zero (the vertex crosses the edge y = 0). A contact at a double (t = 1/2) is
// proven and bracketed, but not rounded: the cubic is zero at the root.
TEST(ExactCcdFilter, DeclinesWhatItCannotProve) {
  for (const CcdQuery& q : {make(CcdKind::VertexFace, {Vec3(-0.5, 0.25, 0), O, X, Y}, {Vec3(0.5, 0.25, 0), O, X, Y}),
                            make(CcdKind::VertexFace, {Vec3(0.5, 0, 1), O, X, Y}, {Vec3(0.5, 0, -0.75), O, X, Y})})
    EXPECT_EQ(certified_float_ccd(q).kind, Kind::Unproven);
  const CcdFilterVerdict half =
      certified_float_ccd(make(CcdKind::VertexFace, {Vec3(0.25, 0.25, 1), O, X, Y}, {Vec3(0.25, 0.25, -1), O, X, Y}));
  EXPECT_EQ(half.kind, Kind::Hit);
  EXPECT_LT(half.lo, 0.5);
  EXPECT_GT(half.hi, 0.5);
  EXPECT_FALSE(half.toi.has_value());
}

// exact_ccd_hit answers the hit without the time: the filter's proven verdicts as they stand,
// the exact path for the rest. On generic queries, near contacts at every scale (proven and
// declined alike) and the declined cases above, it must be the exact path's hit.
TEST(ExactCcdHit, IsTheExactPathsHit) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> ulps(-3, 3);
  int hits = 0, declined = 0;
  const auto check = [&](const CcdQuery& q) {
    const bool expected = exact_ccd_unfiltered(q).hit;
    EXPECT_EQ(exact_ccd_hit(q), expected);
    hits += expected;
    declined += certified_float_ccd(q).kind == Kind::Unproven;
  };
  for (int i = 0; i < 1000; ++i) {
    CcdQuery q;
    q.kind = i % 2 ? CcdKind::VertexFace : CcdKind::EdgeEdge;
    for (std::size_t k = 0; k < 4; ++k) {
      q.x0[k] = random_vec(rng, 1);
      q.x1[k] = q.x0[k] + random_vec(rng, 0.5);
    }
    SCOPED_TRACE(i);
    check(q);
  }
  for (int i = 0; i < 1000; ++i) {
    const double t = (1 + i % 7) / 8.0;
    const bool edge = i % 4 >= 2;
    ccd_cases::Known k =
        i % 2 ? ccd_cases::vf_translation(
                    rng, t, edge ? std::array<double, 3>{0, 0.5, 0.5} : std::array<double, 3>{0.25, 0.25, 0.5})
              : ccd_cases::ee_translation(rng, t, edge ? 1.0 : 0.25, 0.5);
    const double scale = std::ldexp(1.0, (i % 5 - 2) * 40);
    for (std::size_t j = 0; j < 4; ++j) {
      k.q.x0[j] *= scale;
      k.q.x1[j] *= scale;
      for (int c = 0; c < 3; ++c) {
        const int n = ulps(rng);
        for (int s = 0; s < std::abs(n); ++s) k.q.x1[j][c] = std::nextafter(k.q.x1[j][c], n > 0 ? INFINITY : -INFINITY);
      }
    }
    SCOPED_TRACE(i);
    check(k.q);
  }
  for (const CcdQuery& q : {make(CcdKind::VertexFace, {Vec3(-0.5, 0.25, 0), O, X, Y}, {Vec3(0.5, 0.25, 0), O, X, Y}),
                            make(CcdKind::VertexFace, {Vec3(0.5, 0, 1), O, X, Y}, {Vec3(0.5, 0, -0.75), O, X, Y})})
    check(q);
  EXPECT_GT(hits, 300);     // both answers are exercised
  EXPECT_GT(declined, 100);  // and so is the exact path behind the filter
  EXPECT_THROW(exact_ccd_hit(make(CcdKind::EdgeEdge, {Vec3(NAN, 0, 0), O, X, Y}, {O, O, X, Y})), std::domain_error);
}

}  // namespace
}  // namespace tecido::reference
