#pragma once
/// The exact continuous-collision referee (engine name `exact`): vertex-face and edge-edge
/// queries over linear motion (core/geometry/ccd/query.h), answered without error for any finite
/// double input and for rational input given as numerator/denominator decimal integers (the
/// form of the CCD benchmark of Wang, Ferguson, Schneider, Jiang, Attene and Panozzo, ACM TOG
/// 2021, whose ground truth is exact symbolic computation, as here).
///
/// Method (exact_ccd.cpp): the input is scaled to integers (contact times do not change under a
/// uniform scaling of space); contact at time t needs the four points coplanar, the zero set of
/// the cubic f(t) = det[...] with integer coefficients. When f is not identically zero, its real
/// roots in [0, 1] are isolated exactly (square-free part, Descartes' rule of signs on Bernstein
/// coefficients, bisection at dyadic points) and, in increasing order, the closed primitives are
/// tested at each root: signs of integer polynomials at an algebraic number, found by refining
/// its isolating interval until the polynomial's Bernstein coefficients share a sign, or shown
/// to be zero by a common factor (gcd) with the root's defining polynomial. When f is
/// identically zero (coplanar throughout) the earliest contact is at t = 0 or at a time when a
/// vertex reaches an edge, so the answer is the earliest of a few vertex-edge problems, again
/// exact. Degenerate triangles and edges are the point sets they span. In front sits a
/// floating-point filter whose every verdict is certified (exact_ccd_filter.h).
/// Only core types and the standard library cross this header; GMP stays inside exact_ccd.cpp.
#include "core/geometry/ccd/query.h"

#include <array>
#include <string>

namespace tecido::reference {

/// The referee's answer: whether the closed primitives touch at some t in [0, 1], and the
/// earliest such time t*, a real number in [0, 1] reported through doubles.
struct ExactCcd {
  bool hit = false;
  /// The double nearest to t* (ties to even). 0 when !hit.
  double toi = 0.0;
  /// toi_lo <= t* <= toi_hi, adjacent doubles; both equal toi when t* is a double. 0 when !hit.
  double toi_lo = 0.0, toi_hi = 0.0;
  /// True when t* is exactly the double `toi` (no rounding happened).
  bool toi_exact = false;
};

/// The referee's answer as a core CcdAnswer (hit, toi).
inline CcdAnswer to_ccd_answer(const ExactCcd& e) { return CcdAnswer{e.hit, e.hit ? e.toi : 0.0}; }

/// Vertex-face or edge-edge continuous collision, decided exactly on the given doubles taken as
/// the exact rationals they represent. Throws std::domain_error if a coordinate is NaN or
/// infinite.
ExactCcd exact_ccd(const CcdQuery& q);

/// exact_ccd(q).hit, without the time of contact: a contact at a vertex proven without GMP
/// (exact_ccd_feature_contact.h) or a verdict of the floating-point filter is returned as it
/// stands (the exact path would only narrow its time), so GMP runs only on queries neither can
/// decide, and there stops at the first root where the primitives touch, without rounding it to
/// doubles. For confirming candidates (tecido selfcollide --to).
bool exact_ccd_hit(const CcdQuery& q);

/// The same answer computed by the exact path alone, without the floating-point filter in front
/// (for testing the filter and measuring what it saves).
ExactCcd exact_ccd_unfiltered(const CcdQuery& q);

/// A rational coordinate num / den, both decimal integers of any length with an optional sign
/// ("-3002399750379371", "36028797018963968"); den != 0.
struct RationalCoord {
  std::string num, den;
};

/// A CcdQuery with rational coordinates, laid out as CcdQuery (x0 at t = 0, x1 at t = 1).
struct RationalCcdQuery {
  CcdKind kind = CcdKind::VertexFace;
  std::array<std::array<RationalCoord, 3>, 4> x0, x1;
};

/// The same exact decision on rational input. Throws std::invalid_argument on a malformed
/// integer (anything but an optional sign and decimal digits) or a zero denominator.
ExactCcd exact_ccd(const RationalCcdQuery& q);

/// Whether the rational is exactly a (finite) double. Throws as exact_ccd(RationalCcdQuery).
bool is_exact_double(const RationalCoord& c);

/// The double nearest to the rational (IEEE round to nearest, ties to even; +-infinity beyond
/// the largest double), what a floating-point engine is given. Throws as exact_ccd(RationalCcdQuery).
double nearest_double(const RationalCoord& c);

/// The query with every coordinate replaced by nearest_double (for the floating-point engines).
CcdQuery nearest_double_query(const RationalCcdQuery& q);

}  // namespace tecido::reference
