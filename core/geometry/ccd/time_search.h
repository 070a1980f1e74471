#pragma once
/// The time search of core's continuous collision test (ccd/ccd.h): bisection of [0, 1], earliest
/// half first, on certified Bernstein bounds of the coplanarity cubic f
/// (ccd/coplanarity_cubic.h) and of the projected barycentric quadratics
/// (ccd/projected_quadratics.h). On each interval I (E: the coefficients' error bound at that
/// depth, sigma the certain sign of den on I once it has one; signs certified on an interval
/// are inherited by its halves):
///  1. miss on I when f is certainly nonzero on I (no coplanar instant, so no contact);
///  2. miss on I when den has a certain sign and some numerator certainly the opposite sign on
///     I (at any coplanar instant in I the contact point is outside the face or the segments);
///     once every numerator is certainly inside, only the cubic is followed;
///  J. when f certainly changes sign on I and is certainly monotone (its coefficients'
///     differences all of one sign beyond 2E), it has exactly one root in I: a safeguarded
///     Newton iteration approximates it, a bracket [a, b] (b - a = 3h, h a power of two from
///     2^-46 up to time_tolerance / 4) is certified by the cubic restricted to it, and the
///     quadratics restricted to [a, b] decide all of I (rule 2 there is a miss for I, rule 3a
///     there a hit at a, otherwise the inclusion search on [a, b]);
///  3. hits, with beta = distance_tolerance / 27.72 (a barycentric slack worth delta / 2):
///     a. on a leaf (no wider than the time tolerance), f(lo) and f(hi) of certainly opposite
///        signs and every numerator above -beta |den| all over the leaf: at the coplanar
///        instant the point is within delta / 2 of the primitives;
///     b. at lo (any width), or at hi of a leaf, or at hi when the cubic restricted to
///        [lo, hi - tau] is certainly nonzero (then the hit is at hi - tau): |f| / |den| <=
///        delta / 2 and every numerator >= -beta |den| there, so the primitives are within
///        delta of each other at that instant (coplanar motion, contact at t = 0 or 1,
///        sliding);
///  4. otherwise split I, or hand it to the inclusion search (ccd/inclusion.h) when it is no
///     wider than 2^-50, when den vanishes on I (degenerate face, parallel edges: the
///     projection says nothing), or when the node budget is spent.
/// Rules 1, 2 and J's exclusions are certified, the inclusion search is complete, and
/// intervals are visited in time order, so no contact is ever missed, and toi (the lower end
/// of where the hit is found) is never later than the true time of impact.
#include "core/geometry/ccd/query.h"
#include "core/geometry/ccd/settings.h"
#include "core/geometry/ccd/stats.h"
#include "core/geometry/ccd/system.h"

namespace tecido {

/// Runs the time search on a prepared system. settings must already be clamped (ccd/ccd.h);
/// stats (this thread's ccd_stats()) receives the counts.
CcdAnswer ccd_time_search(const CcdSystem& s, const CcdSettings& settings, CcdStats& stats);

}  // namespace tecido
