#pragma once
/// Where the contact point lies, as polynomials in time: the barycentric numerators of a
/// continuous collision query projected along a coordinate axis.
///
/// Take the axis k along which the normal X x Y is largest at mid-step and write
/// det2(U, V) = (U x V)_k, the 2-D cross product in the other two coordinates. Whenever the
/// four points are coplanar (f(t) = 0, ccd/coplanarity_cubic.h) and den(t) = det2(X, Y) != 0,
/// the unique solution of F = Z - u X - v Y = 0 is u = det2(Z, Y) / den, v = det2(X, Z) / den
/// (Cramer's rule on the projection; exact at a coplanar instant whatever the axis, since
/// then Z lies in the span of X and Y). So contact at a coplanar instant t needs, with
/// sigma = sign den(t):
///   vertex-face: sigma det2(Z, Y) >= 0, sigma det2(X, Z) >= 0, sigma det2(P, Q) >= 0
///                (u, v and w = 1 - u - v = det2(X - Z, Y - Z) / den);
///   edge-edge:   sigma det2(Z, Y) >= 0, sigma det2(X, Z) >= 0, sigma det2(P, Y) >= 0,
///                sigma det2(X, Q) >= 0 (u, v, 1 - u, 1 - v).
/// Each det2 of two linear vectors is a quadratic in t. A numerator that is certainly of the
/// wrong sign on an interval where den has a certain sign rules out contact there, whatever
/// the cubic does. Off a coplanar instant, the point p' = a + u X + v Y lies at distance
/// |f| / |den| from the vertex along the axis (edge-edge: between the two edge points), the
/// measure of near misses used by the time search (ccd/time_search.h).
#include "core/geometry/ccd/bernstein.h"
#include "core/geometry/ccd/system.h"

namespace tecido {

/// The quadratics of one query, den first, in Bernstein form on [0, 1], with error bounds.
struct CcdProjectedQuadratics {
  int axis = 2;                            ///< the projection axis k
  int count = 0;                           ///< 4 (vertex-face) or 5 (edge-edge)
  CcdErrorBound err[kCcdMaxQuadratics];    ///< per quadratic
};

/// Fills q[j][k] (coefficient j of quadratic k, Bernstein on [0, 1]) and the bounds. Vertex-
/// face fills slot 4 with a copy of slot 3 so that loops can run over all five.
///
/// Coefficients: det2(U0, V0), (det2(U0, V1) + det2(U1, V0)) / 2, det2(U1, V1). Error: an
/// elementary product passes through at most 5 roundings (2 in the differences, multiply,
/// subtract, add; the halving is exact but for underflow), so gamma_5 times the permanent;
/// 8 eps times the computed permanent covers it and the permanent's rounding; 2^-900 covers
/// underflow.
void ccd_projected_quadratics(const CcdSystem& s, double q[3][kCcdMaxQuadratics], CcdProjectedQuadratics& out);

}  // namespace tecido
