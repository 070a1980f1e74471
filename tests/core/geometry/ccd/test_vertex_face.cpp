// Core's continuous vertex-face test (core/geometry/ccd/vertex_face.h): hand-worked queries for
// every degenerate kind (the answer worked out beside each), then constructions with known
// answers over many seeds and scales: zero false negatives, toi never after the true time of
// impact (and within the time tolerance of it for transversal contacts), no hit on misses
// separated by more than the distance tolerance.
#include "core/geometry/ccd/ccd.h"
#include "tests/core/geometry/ccd/test_constructions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tecido {
namespace {

using ccd_test::make;
constexpr CcdKind kVF = CcdKind::VertexFace;
const double kTimeTolerance = CcdSettings{}.time_tolerance;  // 2^-20

// The unit right triangle a = 0, b = x, c = y in the plane z = 0, at rest.
const Vec3 kA(0, 0, 0), kB(1, 0, 0), kC(0, 1, 0);

CcdQuery vertex_through_static_face(const Vec3& p0, const Vec3& p1) {
  return make(kVF, {p0, kA, kB, kC}, {p1, kA, kB, kC});
}

TEST(CcdVertexFace, TransversalHitThroughTheInterior) {
  // p(t) = (0.2, 0.2, 1 - 2t) meets z = 0 at t = 1/2, at (0.2, 0.2): u = v = 0.2, inside.
  const CcdAnswer a = ccd_vertex_face(vertex_through_static_face({0.2, 0.2, 1}, {0.2, 0.2, -1}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_GE(a.toi, 0.5 - kTimeTolerance);
}

TEST(CcdVertexFace, MissOutsideTheFace) {
  // From (0.9, 0.9, 1) to (0.9, 0.9, -1): crosses z = 0 at (0.9, 0.9), u + v = 1.8 > 1,
  // 0.8 / sqrt(2) = 0.57 from the hypotenuse: a miss.
  EXPECT_FALSE(ccd_vertex_face(vertex_through_static_face({0.9, 0.9, 1}, {0.9, 0.9, -1})).hit);
  // Crossing the plane beside edge a-c: x = -0.25 < 0.
  EXPECT_FALSE(ccd_vertex_face(vertex_through_static_face({-0.25, 0.5, -1}, {-0.25, 0.5, 2})).hit);
}

TEST(CcdVertexFace, TouchingTheBoundaryIsAHit) {
  // Through (0.5, 0.5, 0) at t = 1/2: on the hypotenuse u + v = 1 (closed triangle).
  CcdAnswer a = ccd_vertex_face(vertex_through_static_face({0.5, 0.5, 1}, {0.5, 0.5, -1}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  // Through corner b = (1, 0, 0) at t = 1/4: p(t) = (1, 0, 1 - 4t).
  a = ccd_vertex_face(vertex_through_static_face({1, 0, 1}, {1, 0, -3}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.25);
  EXPECT_GE(a.toi, 0.25 - kTimeTolerance);
}

TEST(CcdVertexFace, FaceMovesOntoAStillVertex) {
  // The face rises from z = -1 to z = 1 (z(t) = 2t - 1) under the still vertex (0.25, 0.25, 0):
  // contact at t = 1/2.
  const Vec3 dz(0, 0, 1);
  const CcdQuery q = make(kVF, {Vec3(0.25, 0.25, 0), kA - dz, kB - dz, kC - dz}, {Vec3(0.25, 0.25, 0), kA + dz, kB + dz, kC + dz});
  const CcdAnswer a = ccd_vertex_face(q);
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_GE(a.toi, 0.5 - kTimeTolerance);
}

TEST(CcdVertexFace, CoplanarThroughoutEnteringTheFace) {
  // Everything in z = 0. p(t) = (2 - 3t, 0.2): it crosses the hypotenuse x + y = 1 when
  // 2 - 3t = 0.8, t = 0.4, and stays inside until x = 0 (t = 2/3).
  const CcdAnswer a = ccd_vertex_face(vertex_through_static_face({2, 0.2, 0}, {-1, 0.2, 0}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.4);
  // A hit may come at most delta = 1e-9 L early (L = 3 here, speed 3): 1e-9 in time.
  EXPECT_GE(a.toi, 0.4 - kTimeTolerance - 1e-9);
}

TEST(CcdVertexFace, CoplanarThroughoutMissing) {
  // In z = 0, p(t) = (2 - 3t, 1.5): y = 1.5 > 1 everywhere, never inside.
  EXPECT_FALSE(ccd_vertex_face(vertex_through_static_face({2, 1.5, 0}, {-1, 1.5, 0})).hit);
  // In z = 0, parallel to the hypotenuse at distance 0.1 / sqrt(2) outside: x + y = 1.1.
  EXPECT_FALSE(ccd_vertex_face(vertex_through_static_face({1.1, 0, 0}, {0, 1.1, 0})).hit);
}

TEST(CcdVertexFace, ZeroAreaFaceThroughout) {
  // c = (0.75, 0, 0) lies on segment a-b: the face is the segment [0, 1] x {0} x {0}.
  const Vec3 c(0.75, 0, 0);
  // p(t) = (0.5, 0, 1 - 2t) passes through (0.5, 0, 0) on that segment at t = 1/2: hit.
  CcdAnswer a = ccd_vertex_face(make(kVF, {Vec3(0.5, 0, 1), kA, kB, c}, {Vec3(0.5, 0, -1), kA, kB, c}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_GE(a.toi, 0.5 - kTimeTolerance - 1e-9);
  // p(t) = (0.5, 0.1, 1 - 2t) passes 0.1 beside it: miss.
  EXPECT_FALSE(ccd_vertex_face(make(kVF, {Vec3(0.5, 0.1, 1), kA, kB, c}, {Vec3(0.5, 0.1, -1), kA, kB, c})).hit);
  // The face is one point (all corners at (1, 1, 1)); p(t) = (1, 1, 4t - 1) meets it at t = 1/2.
  const Vec3 o(1, 1, 1);
  a = ccd_vertex_face(make(kVF, {Vec3(1, 1, -1), o, o, o}, {Vec3(1, 1, 3), o, o, o}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_FALSE(ccd_vertex_face(make(kVF, {Vec3(1, 1.5, -1), o, o, o}, {Vec3(1, 1.5, 3), o, o, o})).hit);
}

TEST(CcdVertexFace, ZeroAreaAtTheInstantOfContact) {
  // a = 0, b = (1, 0, 0), c(t) = (0.5, 1 - 2t, 1 - 2t): the face is a segment at t = 1/2,
  // the plane through the x axis and (0, 1, 1) before and after. p(t) = (0.25, 0, 1 - 2t) is
  // in that plane (y = z) only at t = 1/2, where it lies on edge a-b: first contact 1/2.
  const CcdQuery q = make(kVF, {Vec3(0.25, 0, 1), kA, kB, Vec3(0.5, 1, 1)}, {Vec3(0.25, 0, -1), kA, kB, Vec3(0.5, -1, -1)});
  const CcdAnswer a = ccd_vertex_face(q);
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_GE(a.toi, 0.5 - kTimeTolerance - 1e-9);
}

TEST(CcdVertexFace, ContactExactlyAtTheEndsOfTheStep) {
  // Starts on the face at (0.25, 0.25, 0) and leaves: contact at t = 0 exactly.
  CcdAnswer a = ccd_vertex_face(vertex_through_static_face({0.25, 0.25, 0}, {0.25, 0.25, 1}));
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.toi, 0.0);
  // Arrives on the face at t = 1 exactly.
  a = ccd_vertex_face(vertex_through_static_face({0.25, 0.25, 1}, {0.25, 0.25, 0}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 1.0);
  EXPECT_GE(a.toi, 1.0 - kTimeTolerance);
  // Stops 1e-3 short of the face at t = 1: a miss (0.001 >> delta = 1e-9).
  EXPECT_FALSE(ccd_vertex_face(vertex_through_static_face({0.25, 0.25, 1}, {0.25, 0.25, 1e-3})).hit);
}

TEST(CcdVertexFace, VertexSlidingAlongAnEdge) {
  // p slides along edge a-b from (-0.5, 0, 0) to (0.5, 0, 0): it reaches a at t = 1/2.
  CcdAnswer a = ccd_vertex_face(vertex_through_static_face({-0.5, 0, 0}, {0.5, 0, 0}));
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_GE(a.toi, 0.5 - kTimeTolerance - 1e-9);
  // On the edge all along: contact at t = 0.
  a = ccd_vertex_face(vertex_through_static_face({0.25, 0, 0}, {0.75, 0, 0}));
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.toi, 0.0);
  // On the edge's line but beyond b all along (x from 2 to 3): a miss.
  EXPECT_FALSE(ccd_vertex_face(vertex_through_static_face({2, 0, 0}, {3, 0, 0})).hit);
}

TEST(CcdVertexFace, NonFiniteInputIsAConservativeHitAtZero) {
  for (const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                           -std::numeric_limits<double>::infinity()}) {
    CcdQuery q = vertex_through_static_face({0.9, 0.9, 1}, {0.9, 0.9, -1});
    q.x1[2].y() = bad;
    const CcdAnswer a = ccd_vertex_face(q);
    EXPECT_TRUE(a.hit);
    EXPECT_EQ(a.toi, 0.0);
  }
}

TEST(CcdVertexFace, EveryPointEqualIsContactAtZero) {
  const Vec3 o(3, -2, 7);
  const CcdAnswer a = ccd_vertex_face(make(kVF, {o, o, o, o}, {o, o, o, o}));
  EXPECT_TRUE(a.hit);
  EXPECT_EQ(a.toi, 0.0);
}

TEST(CcdVertexFace, HandWorkedCasesHoldAtEveryScale) {
  // The first tests' queries mapped to s x + o: the geometry, hence the answer, is unchanged.
  struct Case {
    CcdQuery q;
    bool hit;
    double toi;
  };
  const Case cases[] = {
      {vertex_through_static_face({0.2, 0.2, 1}, {0.2, 0.2, -1}), true, 0.5},
      {vertex_through_static_face({0.5, 0.5, 1}, {0.5, 0.5, -1}), true, 0.5},
      {vertex_through_static_face({2, 0.2, 0}, {-1, 0.2, 0}), true, 0.4},
      {vertex_through_static_face({0.9, 0.9, 1}, {0.9, 0.9, -1}), false, 0},
      {vertex_through_static_face({2, 1.5, 0}, {-1, 1.5, 0}), false, 0},
      {vertex_through_static_face({-0.5, 0, 0}, {0.5, 0, 0}), true, 0.5},
  };
  // Powers of two (about 1e-300 .. 1e300) and dyadic offsets: the transformed points are exact,
  // so touching stays touching. (Decimal scales round the points: a query that touches
  // exactly may become a true miss by an ulp; the property tests below use decimal scales on
  // contacts that are not on a boundary.)
  for (const int e : {-997, -100, -50, -10, 0, 10, 50, 100, 997}) {
    const double s = std::ldexp(1.0, e);
    for (const Vec3& o : {Vec3(0, 0, 0), Vec3(0.25, -7.125, 2.5)}) {
      for (const Case& c : cases) {
        const CcdAnswer a = ccd_vertex_face(ccd_test::transformed(c.q, s, s * o));
        EXPECT_EQ(a.hit, c.hit) << "scale 2^" << e << " case " << (&c - cases);
        if (c.hit) {
          EXPECT_LE(a.toi, c.toi + 1e-12) << "scale 2^" << e;
          EXPECT_GE(a.toi, c.toi - kTimeTolerance - 1e-9) << "scale 2^" << e;
        }
      }
    }
  }
}

TEST(CcdVertexFace, BuiltTransversalContactsAreFoundOnTime) {
  // Rigid motions through a contact at a chosen time ts, at a point well inside the face:
  // ts is the only coplanar instant, so the first contact. Over seeds and scales.
  ccd_test::Rng r(1997);
  int n = 0;
  for (int k = 0; k < 3000; ++k) {
    const double ts = r.uniform(0.0, 1.0);
    const CcdQuery q0 = ccd_test::built_contact(kVF, r, ts);
    const double s = std::pow(10.0, r.uniform(-30, 30));
    const CcdQuery q = ccd_test::transformed(q0, s, s * r.point(4.0));
    const CcdAnswer a = ccd_vertex_face(q);
    ASSERT_TRUE(a.hit) << "seed step " << k << " scale " << s;
    EXPECT_LE(a.toi, ts + 1e-12) << k;
    EXPECT_GE(a.toi, ts - kTimeTolerance - 1e-12) << k;
    ++n;
  }
  EXPECT_EQ(n, 3000);
}

TEST(CcdVertexFace, BuiltContactsWithRotationAreNeverMissed) {
  // Every point with its own velocity: contact at ts (maybe an earlier one too).
  ccd_test::Rng r(2002);
  for (int k = 0; k < 3000; ++k) {
    const double ts = r.uniform(0.0, 1.0);
    const CcdQuery q0 = ccd_test::built_contact(kVF, r, ts, 0.02);
    const double s = std::pow(10.0, r.uniform(-30, 30));
    const CcdAnswer a = ccd_vertex_face(ccd_test::transformed(q0, s, s * r.point(4.0)));
    ASSERT_TRUE(a.hit) << k;
    EXPECT_LE(a.toi, ts + 1e-12) << k;
    // The same motion backwards touches at 1 - ts.
    const CcdAnswer b = ccd_vertex_face(ccd_test::time_reversed(ccd_test::transformed(q0, s, Vec3::Zero())));
    ASSERT_TRUE(b.hit) << k;
    EXPECT_LE(b.toi, 1.0 - ts + 1e-12) << k;
  }
}

TEST(CcdVertexFace, MissesSeparatedByAMovingPlaneAreMisses) {
  // Vertex on one side of a moving plane, face on the other, gap >= 1e-8 of the points'
  // extent: apart by more than the distance tolerance (1e-9 of the query's scale) at all times.
  ccd_test::Rng r(31337);
  for (int k = 0; k < 4000; ++k) {
    const double gap = std::pow(10.0, r.uniform(-8, -1));
    const CcdQuery q0 = ccd_test::separated(kVF, r, gap, 1.0);
    ASSERT_GT(gap, 1.01e-9 * ccd_test::query_scale(q0) + 1e-13 * ccd_test::query_scale(q0));
    const double s = std::pow(10.0, r.uniform(-30, 30));
    const CcdQuery q = ccd_test::transformed(q0, s, Vec3::Zero());
    EXPECT_FALSE(ccd_vertex_face(q).hit) << k << " gap " << gap;
  }
}

TEST(CcdVertexFace, AnswerDoesNotDependOnTheOrderOfTheCorners) {
  // Random motions (mostly far from any contact within the tolerance): permuting the face's
  // corners or running time backwards must not change whether they touch.
  ccd_test::Rng r(4242);
  for (int k = 0; k < 2000; ++k) {
    CcdQuery q;
    q.kind = kVF;
    for (int i = 0; i < 4; ++i) {
      q.x0[i] = r.point(1.0);
      q.x1[i] = q.x0[i] + r.point(0.5);
    }
    const bool hit = ccd_vertex_face(q).hit;
    CcdQuery p = q;
    std::swap(p.x0[1], p.x0[3]);
    std::swap(p.x1[1], p.x1[3]);
    EXPECT_EQ(ccd_vertex_face(p).hit, hit) << k;
    std::swap(p.x0[2], p.x0[3]);
    std::swap(p.x1[2], p.x1[3]);
    EXPECT_EQ(ccd_vertex_face(p).hit, hit) << k;
    EXPECT_EQ(ccd_vertex_face(ccd_test::time_reversed(q)).hit, hit) << k;
  }
}

TEST(CcdVertexFace, DegenerateFallbackIsExercised) {
  // The zero-area face of ZeroAreaFaceThroughout goes to the inclusion search; the counters
  // say so (a diagnostic: the tests above check the answers).
  const CcdStats before = ccd_stats();
  const Vec3 c(0.75, 0, 0);
  EXPECT_TRUE(ccd_vertex_face(make(kVF, {Vec3(0.5, 0, 1), kA, kB, c}, {Vec3(0.5, 0, -1), kA, kB, c})).hit);
  EXPECT_GT(ccd_stats().inclusion_calls, before.inclusion_calls);
  EXPECT_EQ(ccd_stats().inclusion_caps, before.inclusion_caps);
}

TEST(CcdVertexFace, TimeToleranceBoundsTheTimeOfImpact) {
  // A coarser time tolerance: toi within 2^-8 before the true 0.5 of the transversal crossing.
  CcdSettings st;
  st.time_tolerance = 0x1p-8;
  const CcdAnswer a = ccd_vertex_face(vertex_through_static_face({0.2, 0.3, 1}, {0.2, 0.3, -1}), st);
  EXPECT_TRUE(a.hit);
  EXPECT_LE(a.toi, 0.5);
  EXPECT_GE(a.toi, 0.5 - 0x1p-8);
}

TEST(CcdVertexFace, DispatcherFollowsTheKind) {
  const CcdQuery q = vertex_through_static_face({0.2, 0.2, 1}, {0.2, 0.2, -1});
  const CcdAnswer a = ccd(q), b = ccd_vertex_face(q);
  EXPECT_EQ(a.hit, b.hit);
  EXPECT_EQ(a.toi, b.toi);
}

}  // namespace
}  // namespace tecido
