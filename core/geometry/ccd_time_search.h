#pragma once
/// The time search of core's continuous collision test (ccd.h): bisection of [0, 1], earliest
/// half first, on certified Bernstein bounds of the coplanarity cubic f
/// (ccd_coplanarity_cubic.h) and of the projected barycentric quadratics
/// (ccd_projected_quadratics.h). On each interval I (E: the coefficients' error bound at that
/// depth, sigma the certain sign of den on I when it has one):
///  1. miss on I when f is certainly nonzero on I (no coplanar instant, so no contact);
///  2. miss on I when den has a certain sign and some numerator certainly the opposite sign on
///     I (at any coplanar instant in I the contact point is outside the face or the segments);
///  3. on intervals no wider than the time tolerance, hit when
///     a. f(lo) and f(hi) certainly differ in sign (a coplanar instant t* in I), den has a
///        certain sign and every numerator stays above -beta |den| on I: at t* the points are
///        coplanar and the contact point is at most beta (barycentric units) outside, i.e.
///        within delta / 2 of the primitives (beta = delta / (8 sqrt(3) L), L the query scale);
///     b. or at lo or hi, |f| / |den| <= delta / 2 and every numerator >= -beta |den|: the
///        primitives are within delta of each other at that instant (coplanar motion, contact
///        at t = 0 or t = 1, sliding);
///  4. otherwise split I, or hand it to the inclusion search (ccd_inclusion.h) when I is no
///     wider than the time tolerance, when den vanishes on I (degenerate triangle, parallel
///     edges: the projection says nothing), or when the node budget is spent.
/// Rules 1 and 2 are certified, the inclusion search is complete, and intervals are visited
/// in time order, so no contact is ever missed and toi = lo of the interval that reports the
/// hit is never later than the true time of impact.
#include "core/geometry/ccd_query.h"
#include "core/geometry/ccd_settings.h"
#include "core/geometry/ccd_stats.h"
#include "core/geometry/ccd_system.h"

namespace tecido {

/// Runs the time search on a prepared system. settings must already be clamped (ccd.h);
/// stats (this thread's ccd_stats()) receives the counts.
CcdAnswer ccd_time_search(const CcdSystem& s, const CcdSettings& settings, CcdStats& stats);

}  // namespace tecido
