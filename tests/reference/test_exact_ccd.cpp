// The exact continuous-collision referee on cases whose answers are known independently: worked
// by hand (in the comments), built to touch at a chosen time (ccd_test_cases.h), related by
// symmetries and scalings that cannot change the answer, and cross-checked against an exact
// integer contact test at sampled times.
#include "reference/exact_ccd.h"

#include "tests/reference/ccd_test_cases.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>

namespace tecido::reference {
namespace {

using ccd_cases::make;
using VF = std::array<Vec3, 4>;
constexpr CcdKind kVF = CcdKind::VertexFace;
constexpr CcdKind kEE = CcdKind::EdgeEdge;

const Vec3 O(0, 0, 0), X(1, 0, 0), Y(0, 1, 0);

void expect_hit_at(const CcdQuery& q, double t) {
  const ExactCcd r = exact_ccd(q);
  EXPECT_TRUE(r.hit);
  EXPECT_EQ(r.toi, t);
  EXPECT_EQ(r.toi_lo, t);
  EXPECT_EQ(r.toi_hi, t);
  EXPECT_TRUE(r.toi_exact);
  const ExactCcd u = exact_ccd_unfiltered(q);
  EXPECT_TRUE(u.hit);
  EXPECT_EQ(u.toi, t);
}

void expect_miss(const CcdQuery& q) {
  const ExactCcd r = exact_ccd(q);
  EXPECT_FALSE(r.hit);
  EXPECT_EQ(r.toi, 0.0);
  EXPECT_FALSE(exact_ccd_unfiltered(q).hit);
}

/// Static triangle O, X, Y (z = 0) and a vertex moving from (x, y, 1) to (x, y, -1).
CcdQuery vertex_down_through(double x, double y) {
  return make(kVF, {Vec3(x, y, 1), O, X, Y}, {Vec3(x, y, -1), O, X, Y});
}

/// The sign of a t^2 + b t + c at the double t in (0, 1), exactly (t = M 2^-e, integers in 128 bits).
int sign_quadratic(double t, long a, long b, long c) {
  int e = 0;
  const double m = std::frexp(t, &e);                           // t = m 2^e, m in [0.5, 1)
  const __int128 M = static_cast<__int128>(std::ldexp(m, 53));  // t = M 2^(e - 53)
  const int s = 53 - e;                                         // t = M / 2^s, s <= 60 here
  const __int128 v = a * M * M + b * M * (static_cast<__int128>(1) << s) + c * (static_cast<__int128>(1) << (2 * s));
  return (v > 0) - (v < 0);
}

// ---- vertex-face, worked by hand ----------------------------------------------------------------

// det[b - a, c - a, p - a] = p_z(t) = 1 - 2t: the only root is t = 1/2, where p = (x, y, 0).
TEST(ExactCcdVertexFace, VertexThroughStaticTriangle) {
  expect_hit_at(vertex_down_through(0.25, 0.25), 0.5);  // inside
  expect_hit_at(vertex_down_through(0.5, 0.5), 0.5);    // on the hypotenuse x + y = 1
  expect_hit_at(vertex_down_through(0.5, 0), 0.5);      // on the edge y = 0
  expect_hit_at(vertex_down_through(1, 0), 0.5);        // on the corner X
  expect_miss(vertex_down_through(0.75, 0.75));         // outside
  expect_miss(vertex_down_through(-0.25, 0.25));        // outside, beyond x = 0
  // One ulp outside the hypotenuse: x + y = 1 + 2^-53.
  expect_miss(vertex_down_through(0.5, std::nextafter(0.5, 1.0)));
  expect_hit_at(vertex_down_through(0.5, std::nextafter(0.5, 0.0)), 0.5);  // one ulp inside
  expect_miss(vertex_down_through(std::nextafter(1.0, 2.0), 0));           // one ulp past the corner
}

// A vertex passing above the triangle's plane, never reaching it, and one moving inside the plane
// z = 1/2 parallel to it: the cubic has no root.
TEST(ExactCcdVertexFace, SeparatedByAPlaneMisses) {
  expect_miss(make(kVF, {Vec3(0.25, 0.25, 1), O, X, Y}, {Vec3(0.25, 0.25, 0.125), O, X, Y}));
  expect_miss(make(kVF, {Vec3(-1, 0.25, 0.5), O, X, Y}, {Vec3(2, 0.25, 0.5), O, X, Y}));
  // One ulp short of the plane at t = 1.
  expect_miss(make(kVF, {Vec3(0.25, 0.25, 1), O, X, Y}, {Vec3(0.25, 0.25, 0x1p-1074), O, X, Y}));
}

// Contact at the ends of the step. t = 0: the vertex starts on the face and leaves it
// (p_z = t, root 0). t = 1: it arrives at the end (p_z = 1 - t, root 1).
TEST(ExactCcdVertexFace, ContactAtStartAndEnd) {
  expect_hit_at(make(kVF, {Vec3(0.25, 0.25, 0), O, X, Y}, {Vec3(0.25, 0.25, 1), O, X, Y}), 0.0);
  expect_hit_at(make(kVF, {Vec3(0.25, 0.25, 1), O, X, Y}, {Vec3(0.25, 0.25, 0), O, X, Y}), 1.0);
  expect_hit_at(make(kVF, {Vec3(1, 0, 0), O, X, Y}, {Vec3(5, 5, 5), O, X, Y}), 0.0);  // on a corner
}

// Corner C moves out of the plane: a = O, b = X, c(t) = (0, 1, 2t); n = (b-a) x (c-a) = (0, -2t, 1).
// Vertex p(t) = (1/4, 1/2, 1 - 2t): f = n.p = -t + 1 - 2t = 1 - 3t, root t* = 1/3, not a double.
// At 1/3, p = b' (b - a) + g (c - a) with b' = 1/4, g = 1/2 (z: g 2/3 = 1/3): inside.
TEST(ExactCcdVertexFace, RationalTimeIsRoundedToNearest) {
  const CcdQuery q = make(kVF, {Vec3(0.25, 0.5, 1), O, X, Y}, {Vec3(0.25, 0.5, -1), O, X, Vec3(0, 1, 2)});
  const ExactCcd r = exact_ccd(q);
  ASSERT_TRUE(r.hit);
  EXPECT_FALSE(r.toi_exact);
  EXPECT_EQ(r.toi, 1.0 / 3.0);  // IEEE division is correctly rounded
  EXPECT_EQ(r.toi_hi, std::nextafter(r.toi_lo, 1.0));
  // 3 toi_lo < 1 < 3 toi_hi, exactly (3x is exact as x + 2x with fma).
  EXPECT_LT(std::fma(3.0, r.toi_lo, -1.0), 0.0);
  EXPECT_GT(std::fma(3.0, r.toi_hi, -1.0), 0.0);
  EXPECT_EQ(exact_ccd_unfiltered(q).toi, r.toi);
}

// As above with p(t) = (1/4, t, 1): f = -2t * t + 1 = 1 - 2t^2, root t* = 1/sqrt(2), irrational.
// At t*, p = (1/4, t*, 1) = b' (1,0,0) + g (0, 1, 2t*) with g = t*, 2 t*^2 = 1: inside
// (b' + g = 0.957 <= 1).
TEST(ExactCcdVertexFace, IrrationalTimeIsBracketedByAdjacentDoubles) {
  const CcdQuery q = make(kVF, {Vec3(0.25, 0, 1), O, X, Y}, {Vec3(0.25, 1, 1), O, X, Vec3(0, 1, 2)});
  for (const ExactCcd& r : {exact_ccd(q), exact_ccd_unfiltered(q)}) {
    ASSERT_TRUE(r.hit);
    EXPECT_FALSE(r.toi_exact);
    EXPECT_EQ(r.toi, std::sqrt(0.5));  // IEEE sqrt is correctly rounded
    EXPECT_EQ(r.toi_hi, std::nextafter(r.toi_lo, 1.0));
    EXPECT_LT(sign_quadratic(r.toi_lo, 2, 0, -1), 0);
    EXPECT_GT(sign_quadratic(r.toi_hi, 2, 0, -1), 0);
  }
}

// Coplanar throughout (the 2-D problem): triangle O, X, Y static in z = 0 and a vertex moving in
// z = 0 from (-1/2, 1/4) to (1/2, 1/4) enters across the edge x = 0 at t = 1/2; moving from
// (-1/2, 2) to (1/2, 2) it passes beside.
TEST(ExactCcdVertexFace, CoplanarThroughoutIsTheTwoDimensionalProblem) {
  expect_hit_at(make(kVF, {Vec3(-0.5, 0.25, 0), O, X, Y}, {Vec3(0.5, 0.25, 0), O, X, Y}), 0.5);
  expect_miss(make(kVF, {Vec3(-0.5, 2, 0), O, X, Y}, {Vec3(0.5, 2, 0), O, X, Y}));
  // Sliding along the edge y = 0 from x = -1 to x = 1: on the closed edge from t = 1/2.
  expect_hit_at(make(kVF, {Vec3(-1, 0, 0), O, X, Y}, {Vec3(1, 0, 0), O, X, Y}), 0.5);
  // Inside at t = 0 already.
  expect_hit_at(make(kVF, {Vec3(0.25, 0.25, 0), O, X, Y}, {Vec3(3, 3, 0), O, X, Y}), 0.0);
}

// Coplanar throughout in a rotating plane: a = O, b = X, c(t) = (0, 1 - t, t) spans the plane
// {(x, s(1-t), s t)}; the vertex p(t) = (t - 1/2, (1-t)/2, t/2) stays in it (s = 1/2) with
// barycentric weights (x, 1/2) on (b, c): inside from x = 0, that is t = 1/2.
TEST(ExactCcdVertexFace, CoplanarThroughoutInARotatingPlane) {
  expect_hit_at(make(kVF, {Vec3(-0.5, 0.5, 0), O, X, Y}, {Vec3(0.5, 0, 0.5), O, X, Vec3(0, 0, 1)}), 0.5);
  // The vertex's x offset by 5/4: x = t + 3/4 > 1/2 throughout, outside: a miss.
  expect_miss(make(kVF, {Vec3(0.75, 0.5, 0), O, X, Y}, {Vec3(1.75, 0, 0.5), O, X, Vec3(0, 0, 1)}));
}

// Coplanar throughout, the first contact at an irrational time reached on a rotating edge:
// a = O, b(t) = (1 - t, t, 0), c = (1/2, -1, 0), vertex p(t) = (t, 1/4, 0). p is on line ab when
// b_x p_y - b_y p_x = (1 - t)/4 - t^2 = 0, i.e. 4t^2 + t - 1 = 0, t* = (sqrt(17) - 1)/8 = 0.3904;
// there p = s b with s = t*/(1 - t*) = 0.64, on the edge. Before t*, p and c are on opposite
// sides of line ab ((1-t)/4 - t^2 > 0 > -1 + t/2), so p is outside.
TEST(ExactCcdVertexFace, CoplanarThroughoutIrrationalTime) {
  const Vec3 c(0.5, -1, 0);
  const CcdQuery q = make(kVF, {Vec3(0, 0.25, 0), O, X, c}, {Vec3(1, 0.25, 0), O, Y, c});
  const ExactCcd r = exact_ccd(q);
  ASSERT_TRUE(r.hit);
  EXPECT_FALSE(r.toi_exact);
  EXPECT_EQ(r.toi_hi, std::nextafter(r.toi_lo, 1.0));
  EXPECT_LT(sign_quadratic(r.toi_lo, 4, 1, -1), 0);
  EXPECT_GT(sign_quadratic(r.toi_hi, 4, 1, -1), 0);
  EXPECT_NEAR(r.toi, (std::sqrt(17.0) - 1) / 8, 1e-16);
}

// A triangle that collapses to a segment: a = O, b = X, c(t) = (1/2, 1 - 2t, 0), collinear at
// t = 1/2; vertex p(t) = (x, 0, 1 - 2t). n = (0, 0, 1 - 2t), f = n.p = (1 - 2t)^2: a double root
// at 1/2 with no sign change, where the triangle is the segment [O, X] and p = (x, 0, 0).
TEST(ExactCcdVertexFace, TriangleCollapsingToASegment) {
  auto q = [](double x) {
    return make(kVF, {Vec3(x, 0, 1), O, X, Vec3(0.5, 1, 0)}, {Vec3(x, 0, -1), O, X, Vec3(0.5, -1, 0)});
  };
  expect_hit_at(q(0.25), 0.5);
  expect_hit_at(q(1), 0.5);  // the segment's end
  expect_miss(q(1.5));
  expect_miss(q(std::nextafter(1.0, 2.0)));
}

// All three corners meet at (1/2, 1/2, 0) at t = 1/2 (a zero-area triangle that is a point);
// the vertex passes through that point then, or beside it.
TEST(ExactCcdVertexFace, TriangleCollapsingToAPoint) {
  const Vec3 m(0.5, 0.5, 0);
  auto q = [&](const Vec3& through) {
    const VF at{through, m, m, m}, v{Vec3(0, 0, -1), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, -1, 0.5)};
    return ccd_cases::moving_through(kVF, 0.5, at, v);
  };
  expect_hit_at(q(m), 0.5);
  expect_miss(q(Vec3(0.5, 0.5 + 0x1p-20, 0)));
}

// A degenerate triangle for the whole step (two equal corners): it is the segment between them.
TEST(ExactCcdVertexFace, ZeroAreaTriangleThroughout) {
  // Segment O-X (corner X doubled); the vertex falls onto it at t = 1/2 (coplanar throughout,
  // since a zero normal makes the cubic vanish).
  expect_hit_at(make(kVF, {Vec3(0.5, 0, 1), O, X, X}, {Vec3(0.5, 0, -1), O, X, X}), 0.5);
  expect_miss(make(kVF, {Vec3(0.5, 0.125, 1), O, X, X}, {Vec3(0.5, 0.125, -1), O, X, X}));
  // All corners equal: a point.
  expect_hit_at(make(kVF, {Vec3(0, 0, 1), O, O, O}, {Vec3(0, 0, -1), O, O, O}), 0.5);
}

// Scaling space changes no contact time: the worked case at 2^100, 2^-100, 1e30 and 1e-30 (every
// coordinate a power of two times the factor, so the scaled inputs are exact).
TEST(ExactCcdVertexFace, HugeAndTinyScales) {
  for (double s : {0x1p100, 0x1p-100, 1e30, 1e-30}) {
    SCOPED_TRACE(s);
    expect_hit_at(make(kVF, {Vec3(0.25, 0.25, 1) * s, O, X * s, Y * s}, {Vec3(0.25, 0.25, -1) * s, O, X * s, Y * s}),
                  0.5);
    expect_miss(make(kVF, {Vec3(0.5, 0.5 + 0x1p-30, 1) * s, O, X * s, Y * s},
                     {Vec3(0.5, 0.5 + 0x1p-30, -1) * s, O, X * s, Y * s}));
  }
}

// ---- edge-edge, worked by hand --------------------------------------------------------------------

/// Edge A from (-1, 0, 0) to (1, 0, 0), static; edge B parallel to y at x = bx, from
/// (bx, -1, z) to (bx, 1, z), z = 1 - 2t. m = (2,0,0) x (0,2,0) = (0,0,4), f = 4 z: root 1/2.
CcdQuery crossing(double bx) {
  const Vec3 a0(-1, 0, 0), a1(1, 0, 0);
  return make(kEE, {a0, a1, Vec3(bx, -1, 1), Vec3(bx, 1, 1)}, {a0, a1, Vec3(bx, -1, -1), Vec3(bx, 1, -1)});
}

TEST(ExactCcdEdgeEdge, CrossingEdges) {
  expect_hit_at(crossing(0), 0.5);
  expect_hit_at(crossing(1), 0.5);  // B passes through A's end point
  expect_miss(crossing(std::nextafter(1.0, 2.0)));
  expect_miss(crossing(2));
}

// End point meets end point: b0(t) = (1, 0, 1 - 2t) reaches a1 = (1, 0, 0) at t = 1/2.
TEST(ExactCcdEdgeEdge, EndPointsTouching) {
  const Vec3 a0(0, 0, 0), a1(1, 0, 0);
  auto q = [&](double x) {
    return make(kEE, {a0, a1, Vec3(x, 0, 1), Vec3(x, 1, 1)}, {a0, a1, Vec3(x, 0, -1), Vec3(x, 1, -1)});
  };
  expect_hit_at(q(1), 0.5);
  expect_miss(q(std::nextafter(1.0, 2.0)));
}

// Parallel edges are coplanar throughout: A = [-1, 1] on the x axis, B on the line y = 1 - 2t,
// z = 0: collinear with A at t = 1/2, when they overlap (B = [1/2, 2]) or not (B = [2, 3]).
TEST(ExactCcdEdgeEdge, ParallelEdges) {
  auto q = [](double b0, double b1) {
    return make(kEE, {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(b0, 1, 0), Vec3(b1, 1, 0)},
                {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(b0, -1, 0), Vec3(b1, -1, 0)});
  };
  expect_hit_at(q(0.5, 2), 0.5);
  expect_hit_at(q(1, 2), 0.5);  // end point on end point
  expect_miss(q(2, 3));
  // Parallel in different planes: z = 1 for B, never coplanar.
  expect_miss(make(kEE, {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 1), Vec3(1, 1, 1)},
                   {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(0, -1, 1), Vec3(1, -1, 1)}));
}

// Collinear throughout: A = [0, 1] static on the x axis, B = [2 - 5t, 3 - 5t] on it too; B's
// start reaches A's end at 2 - 5t = 1, t = 1/5 (not a double).
TEST(ExactCcdEdgeEdge, CollinearSliding) {
  const CcdQuery q = make(kEE, {O, X, Vec3(2, 0, 0), Vec3(3, 0, 0)}, {O, X, Vec3(-3, 0, 0), Vec3(-2, 0, 0)});
  const ExactCcd r = exact_ccd(q);
  ASSERT_TRUE(r.hit);
  EXPECT_EQ(r.toi, 0.2);
  EXPECT_FALSE(r.toi_exact);
  EXPECT_LT(std::fma(5.0, r.toi_lo, -1.0), 0.0);
  EXPECT_GT(std::fma(5.0, r.toi_hi, -1.0), 0.0);
  // Overlapping at t = 0 already.
  expect_hit_at(make(kEE, {O, X, Vec3(0.5, 0, 0), Vec3(3, 0, 0)}, {O, X, Vec3(5, 0, 0), Vec3(8, 0, 0)}), 0.0);
  // Moving apart from disjoint: a miss.
  expect_miss(make(kEE, {O, X, Vec3(2, 0, 0), Vec3(3, 0, 0)}, {O, X, Vec3(4, 0, 0), Vec3(5, 0, 0)}));
}

// Zero-length edges: A is the point (1/2, 0, 1 - 2t) (both ends equal), B = [O, X] static; the
// point lands on B at t = 1/2. Two points meet when both are points.
TEST(ExactCcdEdgeEdge, ZeroLengthEdges) {
  const Vec3 p0(0.5, 0, 1), p1(0.5, 0, -1);
  expect_hit_at(make(kEE, {p0, p0, O, X}, {p1, p1, O, X}), 0.5);
  expect_hit_at(make(kEE, {O, X, p0, p0}, {O, X, p1, p1}), 0.5);
  const Vec3 q0(1.5, 0, 1), q1(1.5, 0, -1);
  expect_miss(make(kEE, {q0, q0, O, X}, {q1, q1, O, X}));
  const Vec3 m(0.5, 0, 0);
  expect_hit_at(make(kEE, {p0, p0, m, m}, {p1, p1, m, m}), 0.5);
  expect_miss(make(kEE, {q0, q0, m, m}, {q1, q1, m, m}));
  // An edge shrinking to a point at t = 1/2 exactly where B crosses: a = (x, 0, 0) +- (1 - 2t, 0, 0).
  expect_hit_at(make(kEE, {Vec3(-1, 0, 0), X, Vec3(0, -1, 1), Vec3(0, 1, 1)},
                     {X, Vec3(-1, 0, 0), Vec3(0, -1, -1), Vec3(0, 1, -1)}),
                0.5);
}

TEST(ExactCcdEdgeEdge, ContactAtStartAndEnd) {
  // Crossing at t = 0, then B rises: f = 4 z, z = t.
  expect_hit_at(
      make(kEE, {Vec3(-1, 0, 0), X, Vec3(0, -1, 0), Vec3(0, 1, 0)}, {Vec3(-1, 0, 0), X, Vec3(0, -1, 1), Vec3(0, 1, 1)}),
      0.0);
  // Reaching A at t = 1.
  expect_hit_at(
      make(kEE, {Vec3(-1, 0, 0), X, Vec3(0, -1, 1), Vec3(0, 1, 1)}, {Vec3(-1, 0, 0), X, Vec3(0, -1, 0), Vec3(0, 1, 0)}),
      1.0);
}

TEST(ExactCcdEdgeEdge, HugeAndTinyScales) {
  for (double s : {0x1p100, 0x1p-100, 1e30, 1e-30}) {
    SCOPED_TRACE(s);
    CcdQuery q = crossing(1), m = crossing(std::nextafter(1.0, 2.0));
    for (auto* c : {&q, &m})
      for (std::size_t i = 0; i < 4; ++i) {
        c->x0[i] *= s;
        c->x1[i] *= s;
      }
    expect_hit_at(q, 0.5);
    if (s == 0x1p100 || s == 0x1p-100) expect_miss(m);  // exact scalings only (1e30 rounds 1 + ulp)
  }
}

// ---- constructions and symmetries ------------------------------------------------------------------

// Rigid translations through a chosen point at a chosen time (ccd_test_cases.h): hits at exactly
// t when the point is on the closed primitives, misses when it is 1/16 outside.
TEST(ExactCcdConstructed, TranslationsHitAtTheChosenTime) {
  std::mt19937 rng(20211);
  const double w = 1.0 / 16;
  for (int i = 0; i < 200; ++i) {
    const double t = (i % 9) / 8.0;
    const std::array<std::array<double, 3>, 6> bary{{{0.25, 0.25, 0.5},
                                                     {0, 0.5, 0.5},  // on an edge
                                                     {0, 0, 1},      // on a corner
                                                     {-w, 0.5, 0.5 + w},
                                                     {1 + w, -w, 0},
                                                     {0.5, 0.75, -0.25}}};
    const auto vf = ccd_cases::vf_translation(rng, t, bary[static_cast<std::size_t>(i % 6)]);
    SCOPED_TRACE(i);
    if (vf.hit) {
      expect_hit_at(vf.q, vf.toi);
    } else {
      expect_miss(vf.q);
    }
    const std::array<std::array<double, 2>, 6> uv{
        {{0.5, 0.5}, {0, 0.25}, {1, 1}, {-w, 0.5}, {0.5, 1 + w}, {1 + w, -w}}};
    const auto& [u, v] = uv[static_cast<std::size_t>(i % 6)];
    const auto ee = ccd_cases::ee_translation(rng, t, u, v);
    if (ee.hit) {
      expect_hit_at(ee.q, ee.toi);
    } else {
      expect_miss(ee.q);
    }
  }
}

/// The same query with the triangle's corners in another order, or the edges swapped or reversed:
/// the same point sets, so the same answer.
TEST(ExactCcdConstructed, AnswersDoNotDependOnTheOrderOfCornersOrEdges) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> d(-2, 2);
  auto pt = [&] { return Vec3(d(rng), d(rng), d(rng)); };
  for (int i = 0; i < 300; ++i) {
    CcdQuery q;
    q.kind = i % 2 ? kVF : kEE;
    for (std::size_t k = 0; k < 4; ++k) {
      q.x0[k] = pt();
      q.x1[k] = pt();
    }
    const ExactCcd r = exact_ccd(q);
    auto permuted = [&](std::array<std::size_t, 4> p) {
      CcdQuery o = q;
      for (std::size_t k = 0; k < 4; ++k) {
        o.x0[k] = q.x0[p[k]];
        o.x1[k] = q.x1[p[k]];
      }
      return o;
    };
    const std::array<std::array<std::size_t, 4>, 3> perms =
        q.kind == kVF ? std::array<std::array<std::size_t, 4>, 3>{{{0, 2, 3, 1}, {0, 3, 2, 1}, {0, 1, 3, 2}}}
                      : std::array<std::array<std::size_t, 4>, 3>{{{2, 3, 0, 1}, {1, 0, 2, 3}, {3, 2, 1, 0}}};
    for (const auto& p : perms) {
      const ExactCcd o = exact_ccd(permuted(p));
      EXPECT_EQ(o.hit, r.hit) << i;
      EXPECT_EQ(o.toi, r.toi) << i;
      EXPECT_EQ(o.toi_lo, r.toi_lo) << i;
    }
  }
}

// ---- dense sampling cross-check ---------------------------------------------------------------------

/// Exact discrete contact test on integer points (an implementation independent of the
/// referee's: 2-D orientations in the projection that keeps the normal, coordinate boxes for
/// collinear points).
struct Discrete {
  using P = std::array<std::int64_t, 3>;
  static P sub(const P& a, const P& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
  static P cross(const P& a, const P& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  }
  static std::int64_t dot(const P& a, const P& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
  static bool zero(const P& a) { return a[0] == 0 && a[1] == 0 && a[2] == 0; }
  static int sgn(std::int64_t v) { return (v > 0) - (v < 0); }
  /// p on the closed segment uv: collinear and inside the segment's coordinate box.
  static bool on_segment(const P& p, const P& u, const P& v) {
    if (!zero(cross(sub(p, u), sub(v, u)))) return false;
    for (int k = 0; k < 3; ++k)
      if (p[k] < std::min(u[k], v[k]) || p[k] > std::max(u[k], v[k])) return false;
    return true;
  }
  /// 2-D orientation of (a, b, c) in the projection dropping axis k.
  static std::int64_t orient(const P& a, const P& b, const P& c, int k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    return (b[i] - a[i]) * (c[j] - a[j]) - (b[j] - a[j]) * (c[i] - a[i]);
  }
  static int major_axis(const P& n) {
    int k = 0;
    for (int i = 1; i < 3; ++i)
      if (std::llabs(n[i]) > std::llabs(n[k])) k = i;
    return k;
  }
  static bool vertex_face(const P& p, const P& a, const P& b, const P& c) {
    const P n = cross(sub(b, a), sub(c, a));
    if (zero(n)) return on_segment(p, a, b) || on_segment(p, b, c) || on_segment(p, c, a);
    if (dot(n, sub(p, a)) != 0) return false;
    const int k = major_axis(n);
    const int s1 = sgn(orient(a, b, p, k)), s2 = sgn(orient(b, c, p, k)), s3 = sgn(orient(c, a, p, k));
    return (s1 >= 0 && s2 >= 0 && s3 >= 0) || (s1 <= 0 && s2 <= 0 && s3 <= 0);
  }
  static bool edge_edge(const P& a0, const P& a1, const P& b0, const P& b1) {
    const P m = cross(sub(a1, a0), sub(b1, b0));
    if (zero(m))
      return on_segment(a0, b0, b1) || on_segment(a1, b0, b1) || on_segment(b0, a0, a1) || on_segment(b1, a0, a1);
    if (dot(m, sub(b0, a0)) != 0) return false;
    const int k = major_axis(m);
    return sgn(orient(a0, a1, b0, k)) * sgn(orient(a0, a1, b1, k)) <= 0 &&
           sgn(orient(b0, b1, a0, k)) * sgn(orient(b0, b1, a1, k)) <= 0;
  }
};

// Random queries with integer coordinates in [-2, 2] (many of them degenerate: coplanar, parallel,
// collinear, coincident). At t = k/64 the points times 64 are integers, tested exactly by
// Discrete: a contact found at the earliest such sample t_k must be an exact hit with toi <= t_k,
// and an exact miss must have no sampled contact. When the exact time is itself a sample, the
// points touch there.
TEST(ExactCcdSampling, SampledContactsAgreeWithTheReferee) {
  std::mt19937 rng(1234);
  std::uniform_int_distribution<int> d(-2, 2);
  constexpr int N = 64;
  int hits = 0, sampled = 0;
  for (int i = 0; i < 1500; ++i) {
    CcdQuery q;
    q.kind = i % 2 ? kVF : kEE;
    std::array<std::array<std::int64_t, 3>, 4> a{}, b{};
    for (std::size_t k = 0; k < 4; ++k) {
      // Bias towards shared motion (coplanar and parallel cases): copy another point's offset.
      for (std::size_t c = 0; c < 3; ++c) {
        a[k][c] = d(rng);
        b[k][c] = (i % 3 == 0 && k > 0) ? a[k][c] + (b[0][c] - a[0][c]) : d(rng);
      }
      q.x0[k] = Vec3(a[k][0], a[k][1], a[k][2]);
      q.x1[k] = Vec3(b[k][0], b[k][1], b[k][2]);
    }
    auto at = [&](int s) {
      std::array<Discrete::P, 4> p;
      for (std::size_t k = 0; k < 4; ++k)
        for (std::size_t c = 0; c < 3; ++c) p[k][c] = N * a[k][c] + s * (b[k][c] - a[k][c]);
      return q.kind == kVF ? Discrete::vertex_face(p[0], p[1], p[2], p[3])
                           : Discrete::edge_edge(p[0], p[1], p[2], p[3]);
    };
    int first = -1;
    for (int s = 0; s <= N && first < 0; ++s)
      if (at(s)) first = s;
    const ExactCcd r = exact_ccd(q);
    SCOPED_TRACE(i);
    hits += r.hit;
    sampled += first >= 0;
    if (first >= 0) {
      ASSERT_TRUE(r.hit);
      EXPECT_LE(r.toi, static_cast<double>(first) / N);
    }
    if (r.hit && r.toi_exact && std::floor(r.toi * N) == r.toi * N) {
      EXPECT_TRUE(at(static_cast<int>(r.toi * N)));
      if (first >= 0) {
        EXPECT_EQ(r.toi, static_cast<double>(first) / N);
      }
    }
    if (!r.hit) {
      EXPECT_EQ(first, -1);
    }
    EXPECT_EQ(exact_ccd_unfiltered(q).toi, r.toi);
  }
  // The generator must exercise both outcomes (not a hard-coded result: a sanity check of the
  // sample's spread).
  EXPECT_GT(sampled, 100);
  EXPECT_LT(hits, 1500);
}

// ---- rational input and errors ------------------------------------------------------------------------

using Coords = const char* const (&)[4][3];

RationalCcdQuery rational(CcdKind kind, Coords x0, Coords x1, const char* den) {
  RationalCcdQuery q;
  q.kind = kind;
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t k = 0; k < 3; ++k) {
      q.x0[i][k] = {x0[i][k], den};
      q.x1[i][k] = {x1[i][k], den};
    }
  return q;
}

// The worked vertex-face case (vertex (1/4, 1/4, 1 - 2t), triangle O, X, Y) scaled by 1/12 and by
// 10^-40 (coordinates that are not doubles): the contact time is 1/2 still.
TEST(ExactCcdRational, ScaledByNonDyadicFactorsKeepsTheTime) {
  for (const char* den : {"12", "10000000000000000000000000000000000000000"}) {
    // numerators are the coordinates times 4: (1,1,4), O, X = (4,0,0), Y = (0,4,0)
    const char* x0[4][3] = {{"1", "1", "4"}, {"0", "0", "0"}, {"4", "0", "0"}, {"0", "4", "0"}};
    const char* x1[4][3] = {{"1", "1", "-4"}, {"0", "0", "0"}, {"4", "0", "0"}, {"0", "4", "0"}};
    const auto q = rational(kVF, x0, x1, den);
    const ExactCcd r = exact_ccd(q);
    EXPECT_TRUE(r.hit);
    EXPECT_EQ(r.toi, 0.5);
    EXPECT_TRUE(r.toi_exact);
  }
}

// Exactness the doubles cannot carry: the vertex crosses the plane z = 0 at t = 1/2 at
// (1/2 + 10^-30, 1/2), just past the hypotenuse x + y = 1: a miss. Rounded to doubles the
// vertex is at (1/2, 1/2), on the hypotenuse: a hit.
TEST(ExactCcdRational, RoundingToDoublesCanChangeTheAnswer) {
  const char* x = "500000000000000000000000000001";  // (1/2 + 10^-30) * 10^30
  const char* h = "500000000000000000000000000000";
  const char* one = "1000000000000000000000000000000";
  const char* z = "0";
  const char* x0[4][3] = {{x, h, one}, {z, z, z}, {one, z, z}, {z, one, z}};
  const char* x1[4][3] = {{x, h, "-1000000000000000000000000000000"}, {z, z, z}, {one, z, z}, {z, one, z}};
  const auto q = rational(kVF, x0, x1, one);
  EXPECT_FALSE(exact_ccd(q).hit);
  EXPECT_FALSE(is_exact_double(q.x0[0][0]));
  EXPECT_EQ(nearest_double(q.x0[0][0]), 0.5);
  const ExactCcd rounded = exact_ccd(nearest_double_query(q));
  EXPECT_TRUE(rounded.hit);
  EXPECT_EQ(rounded.toi, 0.5);
}

/// 2^n * m in decimal (schoolbook doubling; m small).
std::string pow2_times(int n, unsigned long long m) {
  std::string d = std::to_string(m);
  for (int i = 0; i < n; ++i) {
    int carry = 0;
    for (auto it = d.rbegin(); it != d.rend(); ++it) {
      const int v = (*it - '0') * 2 + carry;
      *it = static_cast<char>('0' + v % 10);
      carry = v / 10;
    }
    if (carry) d.insert(d.begin(), static_cast<char>('0' + carry));
  }
  return d;
}

TEST(ExactCcdRational, DoublesAndNearestDoubles) {
  // The ends of the double range: 2^-1074 (the smallest subnormal), (2^53 - 1) 2^971 (the largest).
  EXPECT_TRUE(is_exact_double({"1", pow2_times(1074, 1)}));
  EXPECT_FALSE(is_exact_double({"1", pow2_times(1075, 1)}));
  EXPECT_EQ(nearest_double({"1", pow2_times(1074, 1)}), 0x1p-1074);
  EXPECT_EQ(nearest_double({"1", pow2_times(1075, 1)}), 0.0);  // a tie, to even
  EXPECT_EQ(nearest_double({"3", pow2_times(1076, 1)}), 0x1p-1074);
  EXPECT_TRUE(is_exact_double({pow2_times(971, (1ULL << 53) - 1), "1"}));
  EXPECT_EQ(nearest_double({pow2_times(971, (1ULL << 53) - 1), "1"}), std::numeric_limits<double>::max());
  EXPECT_FALSE(is_exact_double({pow2_times(972, (1ULL << 53) - 1), "1"}));
  EXPECT_EQ(nearest_double({pow2_times(972, (1ULL << 53) - 1), "1"}), std::numeric_limits<double>::infinity());
  EXPECT_FALSE(is_exact_double({pow2_times(0, (1ULL << 53) + 1), "2"}));  // 54 significant bits

  EXPECT_TRUE(is_exact_double({"3", "4"}));
  EXPECT_TRUE(is_exact_double({"-6004799503160661", "36028797018963968"}));
  EXPECT_FALSE(is_exact_double({"1", "3"}));
  EXPECT_FALSE(is_exact_double({"9007199254740993", "1"}));  // 2^53 + 1
  EXPECT_EQ(nearest_double({"1", "3"}), 1.0 / 3.0);
  EXPECT_EQ(nearest_double({"-2", "-6"}), 1.0 / 3.0);
  EXPECT_EQ(nearest_double({"-1", "3"}), -1.0 / 3.0);
  EXPECT_EQ(nearest_double({"9007199254740993", "1"}), 9007199254740992.0);  // tie to even
  EXPECT_EQ(nearest_double({"9007199254740995", "1"}), 9007199254740996.0);  // tie to even
  EXPECT_EQ(nearest_double({"1" + std::string(400, '0'), "1"}), std::numeric_limits<double>::infinity());
  EXPECT_EQ(nearest_double({"1", "1" + std::string(400, '0')}), 0.0);
  EXPECT_EQ(nearest_double({"1", "1" + std::string(320, '0')}), 1e-320);  // subnormal
  EXPECT_EQ(nearest_double({"+7", "2"}), 3.5);
}

TEST(ExactCcdRational, MalformedNumbersAndZeroDenominatorsThrow) {
  EXPECT_THROW(is_exact_double({"1", "0"}), std::invalid_argument);
  EXPECT_THROW(is_exact_double({"1x", "2"}), std::invalid_argument);
  EXPECT_THROW(is_exact_double({" 1", "2"}), std::invalid_argument);
  EXPECT_THROW(is_exact_double({"1 2", "2"}), std::invalid_argument);
  EXPECT_THROW(is_exact_double({"", "2"}), std::invalid_argument);
  EXPECT_THROW(is_exact_double({"-", "2"}), std::invalid_argument);
  EXPECT_THROW(nearest_double({"1.5", "2"}), std::invalid_argument);
  const char* zeros[4][3] = {{"0", "0", "0"}, {"0", "0", "0"}, {"0", "0", "0"}, {"0", "0", "0"}};
  RationalCcdQuery q = rational(kEE, zeros, zeros, "1");
  EXPECT_TRUE(exact_ccd(q).hit);  // four coincident points at t = 0
  q.x1[2][1].den = "0";
  EXPECT_THROW(exact_ccd(q), std::invalid_argument);
}

TEST(ExactCcdErrors, NonFiniteInputThrowsDomainError) {
  for (double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                     -std::numeric_limits<double>::infinity()}) {
    CcdQuery q = vertex_down_through(0.25, 0.25);
    q.x1[2].y() = bad;
    EXPECT_THROW(exact_ccd(q), std::domain_error);
    EXPECT_THROW(exact_ccd_unfiltered(q), std::domain_error);
    q.kind = kEE;
    EXPECT_THROW(exact_ccd(q), std::domain_error);
  }
}

}  // namespace
}  // namespace tecido::reference
