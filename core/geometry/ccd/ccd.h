#pragma once
/// Core's continuous collision test: vertex-face and edge-edge, every point moving linearly
/// over the step t in [0, 1] (the query of ccd/query.h). Zero false negatives by
/// construction: the answer is a hit whenever the closed primitives touch at some t, degenerate
/// motion included; a miss is only ever answered on a certificate.
///
/// Stages, cheapest first (ccd/pipeline.cpp):
///  1. NaN or infinite coordinates: hit at toi = 0 (conservative: such a query has no
///     meaningful answer, and a caller must not take it for a miss).
///  2. Swept boxes (each primitive's box over both frames) disjoint along an axis (exact
///     comparisons), or kinetic boxes (the boxes at t = 0 and 1 interpolated in time) that
///     never overlap: miss (ccd/kinetic_boxes.h; these see through motion the primitives
///     share, e.g. neighbours of a falling cloth).
///  3. The query as differences of its points, translation-free, scaled by a power of two
///     (ccd/system.h): contact is F(t, u, v) = Z - u X - v Y = 0 with (u, v) in the face or on
///     both segments. All points equal at all times: hit at 0.
///  4. The coplanarity cubic f(t) = det(X, Y, Z) in Bernstein form with a rigorous error bound
///     (ccd/coplanarity_cubic.h): certainly nonzero on [0, 1] means never coplanar: miss.
///  5. The time search (ccd/time_search.h), bisection of [0, 1] earliest half first, on the
///     cubic and the barycentric numerators projected along an axis (ccd/projected_quadratics.h),
///     all in Bernstein form with certified bounds: an interval without a coplanar instant, or
///     where the coplanar point is certainly outside, is discarded; where the cubic is certainly
///     monotone with a sign change it has one root, which a safeguarded Newton iteration finds
///     and a certified bracket of width <= 3 * 2^-46 pins down (ccd/cubic_root.h), so the whole
///     interval is decided at once; otherwise hits are reported where a certified crossing
///     with the point inside, or a certified near contact, is found.
///  6. Where the projection says nothing (zero-area face, parallel or zero-length edges,
///     undecided leaves), the inclusion search over (t, u, v) (ccd/inclusion.h, after Wang et
///     al. 2021, "Tight Inclusion"): whole-domain time slabs first (separated along the closest
///     points' direction, a jump to the time of closest approach), then general boxes; a box
///     whose corner values, widened by their rounding bound, exclude 0 is discarded.
///
/// Why no false negative: every "miss" rests on one of
///  - disjoint swept boxes (exact comparisons);
///  - kinetic boxes disjoint at every t (a 1-D linear program with constraints widened past
///    their rounding, crossing times widened past theirs);
///  - a polynomial whose Bernstein coefficients on an interval all exceed a rigorous bound on
///    their rounding error, so the true polynomial has that sign on the whole interval (the
///    coefficients bound it: Farouki and Rajan 1987), where that sign rules out contact (f != 0:
///    never coplanar; a numerator of the wrong sign while den has a certain sign: the coplanar
///    point is outside);
///  - an inclusion box whose corner values all lie beyond their rounding bound on one side of
///    a plane through 0 (the image of the box lies in their convex hull, F being linear in
///    each of t, u, v).
/// The bounds are forward error analyses of the exact operation sequences in the code, in the
/// standard model fl(a op b) = (a op b)(1 + d), |d| <= 2^-53, with absolute pads for underflow
/// (each derivation sits beside its code). Stage 3's scaling keeps every intermediate far from
/// overflow; an overflow anyway gives inf or NaN, which no certificate accepts (comparisons
/// with NaN are false). Intervals are visited in time order, and a search only stops at a hit
/// once everything earlier is excluded. Nothing is tuned: the tolerances below only decide how
/// far a search goes before it says hit. Requires IEEE-754 doubles, round-to-nearest, no
/// -ffast-math and no FMA contraction (the build has none: ISO C++ mode, baseline x86-64).
///
/// Tolerance and false positives (CcdSettings, ccd/settings.h): with L the query's scale
/// (largest coordinate of X, Y, Z at t = 0 and 1) and delta = distance_tolerance * L (default
/// 1e-9 L), a hit means that at some time in [toi, toi + time_tolerance] the primitives come
/// within delta (plus at most 1e-13 L of rounding) of each other, so primitives that stay
/// farther apart over the whole step are always a miss. The exceptions are NaN/Inf input and
/// a query that exhausts the inclusion search's box cap (CcdSettings::max_boxes: hit with
/// toi <= true toi, no distance guarantee); ccd_stats() counts both.
///
/// Time of impact: toi <= the true first time of contact, always (every earlier interval was
/// excluded). A hit comes with a time in [toi, toi + time_tolerance] (default 2^-20, about
/// 9.5e-7) at which the primitives are within delta of each other; when the hit rests on a
/// certified sign change of the cubic (a transversal crossing, the common case), that time is
/// the first contact itself, and it lies typically within 3 * 2^-46 (about 4e-14) of toi.
/// toi is 0 for NaN input.
///
/// Deterministic: the same input gives the same bits on every machine with IEEE doubles, at any
/// thread count (scratch and counters are thread-local).
#include "core/geometry/ccd/edge_edge.h"
#include "core/geometry/ccd/query.h"
#include "core/geometry/ccd/settings.h"
#include "core/geometry/ccd/stats.h"
#include "core/geometry/ccd/vertex_face.h"

namespace tecido {

/// ccd_vertex_face or ccd_edge_edge, as q.kind says.
CcdAnswer ccd(const CcdQuery& q, const CcdSettings& settings);
/// The same with the default settings.
CcdAnswer ccd(const CcdQuery& q);

}  // namespace tecido
