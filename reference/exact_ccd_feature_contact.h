#pragma once
/// Proofs of contact through a sub-feature, for the exact referee's whether-question
/// (exact_ccd_hit): a vertex of one primitive reaching a vertex or an edge of the other. Any such
/// contact is a contact of the closed primitives (a vertex-face query's vertex on an edge or a
/// corner of the triangle, an end point of one segment on the other segment), so a proven one
/// answers "hit" exactly; nothing here ever answers "miss".
///
/// These are the contacts that the floating-point filter (exact_ccd_filter.h) cannot prove, since
/// the primitives touch exactly at a zero of one of its conditions: meshes whose vertices share a
/// coordinate (a cloth folded about an axis keeps each grid row in its plane y = const) make them
/// the rule rather than the exception. The proofs use exact expansion arithmetic (Shewchuk 1997;
/// core/geometry/expansion_arithmetic.h) where a quantity must be exactly zero and certified
/// floating point (certified_float.h) where a sign is strict; no GMP.
#include "core/geometry/ccd/query.h"

namespace tecido::reference {

/// True when the closed primitives of `q` are proven to touch at some t in [0, 1] at a vertex of
/// one lying on a vertex or an edge of the other (false: not proven, either way). Proves:
///   vertex-vertex: p(t) = u(t), exactly (the root of each moving coordinate difference, a
///   rational, compared by cross-multiplication);
///   vertex-edge: (p - u) x (v - u) = 0 with (p - u).(p - v) <= 0, when at most one component
///   of the cross product is not identically zero (checked exactly): that component's sign change
///   over a short interval of doubles (certified), on which the dot product is certified negative
///   (p strictly inside the edge), or a zero at t = 0 or 1 with the dot product's exact sign there.
/// Requires finite input; declines (false) when a non-zero coordinate lies outside
/// [2^-400, 2^400] in magnitude, where the expansions could underflow or overflow.
bool proven_feature_contact(const CcdQuery& q);

}  // namespace tecido::reference
