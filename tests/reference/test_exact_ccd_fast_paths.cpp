// The exact referee's fast paths against its plain GMP path (exact_ccd_unfiltered), which uses
// neither the floating-point filter nor the sub-feature proofs: exact_ccd and exact_ccd_hit must
// give the same answer on every query, random and degenerate (grid-aligned coordinates, shared
// planes, parallel and collinear edges, contacts at t = 0, 1 and in between, zero motion,
// magnitudes near 2^+-500). The sub-feature proofs (exact_ccd_feature_contact.h) are checked on
// their own too: each proven contact is a GMP hit, and they do prove the fold's contacts.
#include "reference/exact_ccd.h"
#include "reference/exact_ccd_feature_contact.h"

#include "tests/reference/ccd_test_cases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace tecido::reference {
namespace {

using ccd_cases::make;

/// exact_ccd, exact_ccd_hit and the sub-feature proof against the GMP-only answer.
void expect_same_as_gmp(const CcdQuery& q, int* proven = nullptr) {
  const ExactCcd gmp = exact_ccd_unfiltered(q);
  const ExactCcd fast = exact_ccd(q);
  ASSERT_EQ(fast.hit, gmp.hit);
  EXPECT_EQ(fast.toi, gmp.toi);
  EXPECT_EQ(fast.toi_lo, gmp.toi_lo);
  EXPECT_EQ(fast.toi_hi, gmp.toi_hi);
  EXPECT_EQ(fast.toi_exact, gmp.toi_exact);
  EXPECT_EQ(exact_ccd_hit(q), gmp.hit);
  const bool feature = proven_feature_contact(q);
  if (feature) {
    EXPECT_TRUE(gmp.hit);  // a proof, never a guess
  }
  if (proven) *proven += feature;
}

/// Coordinates k 2^e with small integers k: many exact coincidences, shared planes and lines.
struct GridQueries {
  std::mt19937_64 rng;
  int range;
  double scale;

  double coordinate() { return scale * std::uniform_int_distribution<int>(-range, range)(rng); }
  Vec3 point() { return Vec3(coordinate(), coordinate(), coordinate()); }

  CcdQuery next() {
    CcdQuery q;
    q.kind = std::uniform_int_distribution<int>(0, 1)(rng) ? CcdKind::EdgeEdge : CcdKind::VertexFace;
    const int motion = std::uniform_int_distribution<int>(0, 3)(rng);
    for (std::size_t i = 0; i < 4; ++i) {
      q.x0[i] = point();
      q.x1[i] = motion == 0 ? q.x0[i] : point();  // motion 0: nothing moves
    }
    // Often all four points keep one coordinate (a shared plane y = c throughout, as a cloth
    // folded about an axis), or three of them do (a vertex and an edge in one plane).
    const int shared = std::uniform_int_distribution<int>(0, 2)(rng);
    if (shared > 0) {
      const double c = coordinate();
      for (std::size_t i = 0; i < (shared == 1 ? 4u : 3u); ++i) q.x0[i].y() = q.x1[i].y() = c;
    }
    return q;
  }
};

TEST(ExactCcdFastPaths, RandomGenericQueriesAgreeWithGmp) {
  std::mt19937_64 rng(20261207);
  std::uniform_real_distribution<double> u(-1, 1), small(-0.3, 0.3);
  for (int n = 0; n < 3000; ++n) {
    CcdQuery q;
    q.kind = n % 2 ? CcdKind::EdgeEdge : CcdKind::VertexFace;
    for (std::size_t i = 0; i < 4; ++i) {
      q.x0[i] = Vec3(u(rng), u(rng), u(rng)) * 0.5;
      q.x1[i] = q.x0[i] + Vec3(small(rng), small(rng), small(rng)) * (n % 3 ? 1.0 : 4.0);
    }
    expect_same_as_gmp(q);
    if (HasFatalFailure()) return;
  }
}

TEST(ExactCcdFastPaths, GridAlignedDegenerateQueriesAgreeWithGmp) {
  int proven = 0, hits = 0, total = 0;
  for (double scale : {1.0, 0x1p-20, 0x1p20, 0x1p-500, 0x1p500})
    for (int range : {1, 2, 4}) {
      GridQueries g{std::mt19937_64(static_cast<unsigned>(range * 977 + 13)), range, scale};
      for (int n = 0; n < 400; ++n) {
        const CcdQuery q = g.next();
        expect_same_as_gmp(q, &proven);
        if (HasFatalFailure()) return;
        hits += exact_ccd_unfiltered(q).hit;
        ++total;
      }
    }
  // The degenerate set is mostly contacts at a vertex; the sub-feature proofs must take a good
  // share of them (they are what makes the fold fast), not merely be sound.
  EXPECT_GT(hits, total / 10);
  EXPECT_GT(proven, hits / 4) << proven << " of " << hits << " hits proven";
}

TEST(ExactCcdFastPaths, MixedMagnitudesAgreeWithGmp) {
  // Coordinates near 2^-600 next to ones near 1: outside the expansions' range, the proofs
  // decline and the GMP path answers.
  GridQueries g{std::mt19937_64(11), 2, 1.0};
  for (int n = 0; n < 300; ++n) {
    CcdQuery q = g.next();
    q.x1[static_cast<std::size_t>(n % 4)].z() += 0x1p-600 * static_cast<double>(n % 3);
    expect_same_as_gmp(q);
    if (HasFatalFailure()) return;
  }
}

/// The fold's configuration: a vertex moving in the plane y = 0 crosses the edge (b, c) of a
/// triangle that lies in y = 0 on that edge and leans out of the plane; it touches the edge
/// only (the filter cannot prove it: the vertex is exactly on the edge's line then).
TEST(ExactCcdFastPaths, VertexThroughATrianglesEdgeInItsPlaneIsProven) {
  const Vec3 a(0.25, 0.5, 0.75), b(0, 0, 0), c(1, 0, 0);
  for (double x : {0.5, 0.125, 0.9}) {
    const CcdQuery q = make(CcdKind::VertexFace, {Vec3(x, 0, 0.5), a, b, c}, {Vec3(x, 0, -0.25), a, b, c});
    EXPECT_TRUE(proven_feature_contact(q));
    EXPECT_TRUE(exact_ccd_unfiltered(q).hit);
    expect_same_as_gmp(q);
  }
  // Past the edge's end: no contact, and no proof.
  const CcdQuery miss = make(CcdKind::VertexFace, {Vec3(1.5, 0, 0.5), a, b, c}, {Vec3(1.5, 0, -0.25), a, b, c});
  EXPECT_FALSE(proven_feature_contact(miss));
  expect_same_as_gmp(miss);
}

/// Two edges in the plane y = 0 throughout (coplanar: the cubic is identically zero) crossing
/// as they move; an end point of one sweeps over the other.
TEST(ExactCcdFastPaths, CoplanarEdgesCrossingAreProven) {
  const CcdQuery q = make(CcdKind::EdgeEdge, {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, 0.25), Vec3(0.75, 0, 1)},
                          {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0.5, 0, -0.5), Vec3(0.75, 0, 0.25)});
  EXPECT_TRUE(proven_feature_contact(q));
  expect_same_as_gmp(q);
}

/// Vertices meeting exactly mid-step: (0,0,0) -> (2,2,2) against (2,0,1) -> (0,2,1), equal at t = 1/2.
TEST(ExactCcdFastPaths, VerticesMeetingMidStepAreProven) {
  const Vec3 far(5, 5, 5);
  const CcdQuery q = make(CcdKind::EdgeEdge, {Vec3(0, 0, 0), far, Vec3(2, 0, 1), -far},
                          {Vec3(2, 2, 2), far, Vec3(0, 2, 1), -far});
  EXPECT_TRUE(proven_feature_contact(q));
  expect_same_as_gmp(q);
  // Shifted by one unit in z at the end: they pass each other without meeting.
  const CcdQuery apart = make(CcdKind::EdgeEdge, {Vec3(0, 0, 0), far, Vec3(2, 0, 1), -far},
                              {Vec3(2, 2, 3), far, Vec3(0, 2, 1), -far});
  expect_same_as_gmp(apart);
}

}  // namespace
}  // namespace tecido::reference
