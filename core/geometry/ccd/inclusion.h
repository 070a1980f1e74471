#pragma once
/// Inclusion-based search over the parameter box (t, u, v): the complete fallback of core's
/// continuous collision test (ccd/ccd.h), used where the time search cannot decide (degenerate
/// motion: coplanar throughout, parallel edges, a triangle of zero area, a vertex crossing
/// exactly through an edge...).
///
/// Method: Wang, Ferguson, Schneider, Jiang, Attene and Panozzo 2021, "A Large-scale Benchmark
/// and an Inclusion-based Algorithm for Continuous Collision Detection" (ACM TOG 40(5), "Tight
/// Inclusion"). F(t, u, v) = Z(t) - u X(t) - v Y(t) (ccd/system.h) is linear in each of t, u
/// and v separately, so over a box it is a convex combination of its values at the box's 8
/// corners (nonnegative weights, products of (1 - s) and s per parameter, summing to 1): its
/// image lies in the convex hull of those 8 values (for a vertex-face slab, of the 6 values at
/// the triangle's corners: F is affine on the triangle). A box whose corner values, widened by
/// their rounding error, all lie beyond 0 in one coordinate, or all on one side of a plane
/// through 0, cannot contain a zero of F and is discarded. Planes tried: normal to the sum of
/// the corner values; normal to X x Y at mid-box (or, when X and Y are parallel, to the part
/// of Z across them: there F hardly depends on (u, v), which separates a thin box from a
/// contact set that is a curve); for a slab, along the closest points at mid-slab (at a fixed
/// time the image of the domain is convex, so that direction separates it from 0 whenever
/// they are apart).
///
/// Order: first whole-domain time slabs (each accepted when the closest points at its lower
/// time are certainly within delta, or at its upper time on a slab within the time
/// tolerance; else a jump: a Newton-like iteration on the time of closest approach of the
/// linearised motion splits the slab around it into pieces that the tests above decide; else
/// bisection in time), then general boxes split along the parameter that changes F most, and
/// accepted when their corner values all lie within delta / 2 of 0 per coordinate. Depth
/// first, earlier half first, as a branch and bound on the time of impact: once a box is
/// accepted at lower time t_b, every other box is clipped to t < t_b (dropped when it starts at
/// or after t_b), and the search goes on until no box is left. So toi = the smallest accepted
/// lower t, and every time before it has been excluded: toi <= the true time of impact.
/// (Taking boxes strictly earliest-first, as a heap would, refines the whole contact set at
/// once when it is a curve, e.g. parallel edges sliding over each other: exponentially many
/// boxes.) Vertex-face boxes over [0, 1]^2 with u0 + v0 > 1 lie outside the triangle and are
/// discarded (u0 + v0 is exact: both are multiples of 2^-52 in [0, 1]).
///
/// Error bound of a corner value (per coordinate c, M_c the largest |component| of X, Y, Z at
/// t = 0 and 1): X(t) = X0 + t (X1 - X0) and the others carry at most 8 eps M_c, u X(t) at most
/// 9 eps M_c, Z - u X 19 eps M_c, F = Z - u X - v Y at most 31 eps M_c (each input also carries
/// its one rounding of ccd/system.h); E_c = 64 eps M_c + 2^-900 (underflow) is used.
#include "core/geometry/ccd/system.h"

namespace tecido {

struct CcdInclusionResult {
  bool hit = false;
  double toi = 0.0;
  bool capped = false;  ///< the box cap was reached: hit without the distance guarantee
  int boxes = 0;        ///< boxes evaluated
};

/// Searches t in [t_lo, t_hi] (dyadic rationals in [0, 1]) and the whole (u, v) domain for a
/// zero of F. Miss only when every box was certified zero-free (so: no contact in that time
/// interval). Hit when a slab's closest points are certainly within delta at its lower time
/// (or at its upper time, the slab no wider than tau), or a box no wider than delta / 2 in
/// every coordinate of F survives (then at t = toi the primitives are within
/// sqrt(3) (delta / 2 + E) of each other, at the box's corner (u0, v0), which lies in the
/// domain), or, conservatively, when max_boxes boxes have been evaluated or every parameter's
/// width is down to 2^-40.
CcdInclusionResult ccd_inclusion_search(const CcdSystem& s, double t_lo, double t_hi, double delta, double tau,
                                        int max_boxes);

}  // namespace tecido
