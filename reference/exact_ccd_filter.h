#pragma once
/// The floating-point filter in front of the exact continuous-collision referee (exact_ccd.h):
/// plain double arithmetic in which every quantity carries a rigorous bound on its rounding
/// error (a running error bound, as in Shewchuk's adaptive predicates, 1997), so that a sign is
/// used only when the bound proves it. It answers when it can prove the answer and otherwise
/// says it cannot; the exact path then decides. Double input only, no GMP.
#include "core/geometry/ccd/query.h"

#include <optional>

namespace tecido::reference {

/// What the filter proved about a query.
struct CcdFilterVerdict {
  enum class Kind { Unproven, Miss, Hit };
  Kind kind = Kind::Unproven;
  /// Hit: the earliest contact time t* is the only root of the coplanarity cubic in the open
  /// interval (lo, hi) (doubles, lo < hi), where the cubic is strictly monotone, with sign
  /// sign_lo (+1 or -1) at lo and the opposite sign at hi.
  double lo = 0.0, hi = 0.0;
  int sign_lo = 0;
  /// Hit: the double nearest to t*, when proven too (then lo and hi are adjacent doubles).
  std::optional<double> toi;
};

/// What certified floating-point arithmetic proves about `q` (Unproven when nothing).
/// Steps, each certified: (1) disjoint swept bounding boxes (exact comparisons) prove a miss;
/// (2) the coplanarity cubic's Bernstein coefficients on [0, 1], computed with error bounds, all
/// of one strict sign prove it has no root, a miss; (3) otherwise its roots are isolated by
/// Bernstein subdivision (de Casteljau at 7/16, depth <= 12) into intervals on which it is
/// provably monotone with a sign change, and at each root in increasing order the in-triangle
/// (vertex-face) or segments-cross (edge-edge) conditions are evaluated over the interval with
/// error bounds, the interval first narrowed in one jump to a few ulps around an approximation
/// of the root (regula falsi; kept only where the cubic's signs prove the root inside), then
/// split (at most 99 times) while they are undecided: a proven contact is a hit, a
/// proven non-contact moves on to the next root, none left is a miss; (4) for a hit the root is
/// narrowed by bisection on the bit patterns of doubles as long as the cubic's sign is proven,
/// and when it is bracketed by adjacent doubles, rounded by the sign at their exact midpoint.
/// The earliest root is usually left a few ulps wide (the cubic's value there is below its
/// rounding error), and a root at a double is never rounded (the cubic vanishes there): exact
/// arithmetic finishes them. Coplanar-throughout motion, roots at the ends of [0, 1] and contacts
/// decided by a zero (touching an edge or corner) are never proven. Requires finite input.
CcdFilterVerdict certified_float_ccd(const CcdQuery& q);

}  // namespace tecido::reference
