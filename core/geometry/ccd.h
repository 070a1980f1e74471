#pragma once
/// Core's continuous collision test: vertex-face and edge-edge, every point moving linearly
/// over the step t in [0, 1] (the query of ccd_query.h). The answer is a hit whenever the
/// closed primitives touch at some t, with no exception for degenerate motion; misses are
/// answered without doubt only when certified.
///
/// Stages, cheapest first (ccd_pipeline.cpp):
///  1. NaN or infinite coordinates: hit at toi = 0 (conservative; such a query has no
///     meaningful answer and a caller must not take it for a miss).
///  2. Swept boxes disjoint along an axis (exact comparisons), or kinetic boxes (the boxes at
///     t = 0 and 1 interpolated in time) that never overlap: miss (ccd_swept_boxes.h,
///     ccd_kinetic_boxes.h; the second sees through motion the primitives share).
///  3. The query as differences of its points, translation-free, scaled by a power of two
///     (ccd_system.h); contact is F(t, u, v) = Z - u X - v Y = 0 with (u, v) in the face or on
///     both segments. All points equal at all times: hit at 0.
///  4. The coplanarity cubic f(t) = det(X, Y, Z) in Bernstein form with a rigorous error bound
///     (ccd_coplanarity_cubic.h): certainly nonzero on [0, 1] means never coplanar: miss.
///  5. The time search (ccd_time_search.h): bisection of [0, 1], earliest half first, on the
///     cubic and the projected barycentric quadratics (ccd_projected_quadratics.h), each with
///     a certified error bound: intervals without a coplanar instant, or where the coplanar
///     point is certainly outside, are discarded; contact is reported at the first interval
///     no wider than the time tolerance where it is certain (a certified sign change of f
///     with the point inside) or where the primitives are within the distance tolerance.
///  6. Where the projection says nothing (zero-area triangle, parallel or zero-length edges,
///     undecided leaves), the inclusion search over (t, u, v) (ccd_inclusion.h, after Wang et
///     al. 2021, "Tight Inclusion"): boxes whose 8 corner values, widened by their rounding
///     bound, exclude 0 are discarded; the others are split, earliest t first.
///
/// Zero false negatives, by construction. Every "miss" is one of: disjoint swept boxes
/// (exact); kinetic boxes disjoint at every time (a linear program over t with widened
/// constraints, ccd_kinetic_boxes.h); a polynomial whose Bernstein coefficients all exceed a rigorous bound on their
/// rounding error (so the true polynomial has one sign on the interval: the coefficients
/// bound it, Farouki and Rajan 1987), where that polynomial's sign rules out contact; or an
/// inclusion box whose corner values all exceed their rounding bound on one side (the image
/// of the box lies in their convex hull, since F is linear in each parameter). The bounds are
/// forward error analyses of the exact operation sequences in the code, in the standard model
/// fl(a op b) = (a op b)(1 + d), |d| <= 2^-53, with absolute pads for underflow; the scaling of
/// stage 3 keeps every intermediate far from overflow, and an overflow would give inf or
/// NaN, which no certification accepts (comparisons with NaN are false). Nothing is tuned:
/// the tolerances below only decide how far the search goes before it says hit. Requires
/// IEEE-754 doubles with round-to-nearest and no -ffast-math; no FMA contraction (the build
/// has none: ISO C++ mode, baseline x86-64).
///
/// Tolerance and false positives (CcdSettings, ccd_settings.h): with L the query's scale
/// (largest coordinate of X, Y, Z at t = 0 and 1) and delta = distance_tolerance * L (default
/// 1e-9 L), a hit means that at some time in [toi, toi + time_tolerance] the primitives come
/// within delta (plus at most 1e-13 L of rounding) of each other. Primitives that stay
/// farther apart over the whole step are a miss. The exceptions are NaN/Inf input and a
/// query that exhausts the inclusion search's box cap (CcdSettings::max_boxes; then hit,
/// toi <= true toi, no distance guarantee); ccd_stats() counts both.
///
/// Time of impact: toi <= the true first time of contact, always (every earlier interval was
/// excluded). For a transversal contact (a certified sign change of f), the first contact
/// lies in [toi, toi + time_tolerance] (default 2^-20 ~ 9.5e-7); in general, the primitives are
/// within delta of each other at some time in that window. toi is 0 for NaN input.
///
/// Deterministic: the same input gives the same bits on every machine with IEEE doubles.
/// Thread-safe (scratch is thread-local).
#include "core/geometry/ccd_edge_edge.h"
#include "core/geometry/ccd_query.h"
#include "core/geometry/ccd_settings.h"
#include "core/geometry/ccd_stats.h"
#include "core/geometry/ccd_vertex_face.h"

namespace tecido {

/// ccd_vertex_face or ccd_edge_edge, as q.kind says.
CcdAnswer ccd(const CcdQuery& q, const CcdSettings& settings);
/// The same with the default settings.
CcdAnswer ccd(const CcdQuery& q);

}  // namespace tecido
