#pragma once
/// libccd 2.1 (Fiser) as a triangle-triangle engine: GJK and MPR boolean intersection of two
/// triangles given by a support function. Only core types cross this header; libccd stays
/// inside ccd_adapter.cpp.
///
/// libccd is a convex-solid library: on flat inputs such as triangles it is unreliable where
/// the Minkowski difference is itself flat or the origin lies on its boundary (touching):
/// coplanar overlap, a shared vertex, edge-edge touching. Those answers are data to compare,
/// not truth (the exact referee settles them).
#include "core/geometry/types.h"

#include <optional>

namespace tecido::reference {

/// Upper bound on GJK iterations handed to libccd (ccd_t::max_iterations). A triangle pair
/// needs fewer than 10 on ordinary inputs; hitting the bound means "could not answer".
inline constexpr unsigned long kCcdMaxIterations = 100;

/// Whether the triangles intersect according to libccd's ccdGJKIntersect (Gilbert, Johnson,
/// Keerthi 1988; libccd's implementation, touching tests with an absolute epsilon DBL_EPSILON).
/// Support function: the vertex with the largest dot product with the direction. GJK's boolean
/// query uses no tolerance parameter (epa_tolerance and dist_tolerance only matter for
/// penetration/distance queries, which are not used). Returns std::nullopt when libccd could
/// not answer: a non-finite input, a NaN search direction, or kCcdMaxIterations exhausted.
std::optional<bool> ccd_gjk_tri_tri(const Triangle& a, const Triangle& b);

/// Whether the triangles intersect according to libccd's ccdMPRIntersect (Minkowski Portal
/// Refinement, Snethen, Game Programming Gems 7, 2008). Same support function; the interior
/// point ("centre") of each triangle is its centroid. mpr_tolerance is left at libccd's
/// default 1e-4 (absolute, in input units): refinement stops, answering "no intersection",
/// once the portal can advance less than that, so near-touching pairs within ~1e-4 of each
/// other may be reported as separated. libccd's MPR intersection ignores max_iterations; the
/// adapter caps support calls itself (4 * kCcdMaxIterations) and then returns std::nullopt, as
/// it does for non-finite inputs and NaN search directions (a flat portal normalised to NaN).
std::optional<bool> ccd_mpr_tri_tri(const Triangle& a, const Triangle& b);

}  // namespace tecido::reference
