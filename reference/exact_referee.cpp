// The only translation unit that includes CGAL (reference/CMakeLists.txt links CGAL::CGAL
// privately; CGAL adds -frounding-math).
#include "reference/exact_referee.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/intersections.h>

#include <cmath>
#include <stdexcept>
#include <variant>

namespace tecido::reference {
namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = K::Point_3;
using Segment = K::Segment_3;
using Tri = K::Triangle_3;
using Q = CGAL::Gmpq;

bool finite(const Vec3& v) { return std::isfinite(v.x()) && std::isfinite(v.y()) && std::isfinite(v.z()); }

Point to_point(const Vec3& v) { return Point(v.x(), v.y(), v.z()); }

/// The point set a (possibly degenerate) triangle really is.
using Shape = std::variant<Tri, Segment, Point>;

Shape shape_of(const Triangle& t) {
  const Point p = to_point(t[0]), q = to_point(t[1]), r = to_point(t[2]);
  if (!CGAL::collinear(p, q, r)) return Tri(p, q, r);
  if (p == q && q == r) return p;
  // Collinear and not all equal: the hull is the segment between the lexicographic extremes.
  Point lo = p, hi = p;
  for (const Point& x : {q, r}) {
    if (CGAL::compare_xyz(x, lo) == CGAL::SMALLER) lo = x;
    if (CGAL::compare_xyz(x, hi) == CGAL::LARGER) hi = x;
  }
  return Segment(lo, hi);
}

bool intersects(const Point& a, const Point& b) { return a == b; }
template <class A, class B>
bool intersects(const A& a, const B& b) {
  return CGAL::do_intersect(a, b);
}

/// An exact 3-vector of rationals.
struct QVec {
  Q x, y, z;
};
QVec qvec(const Vec3& v) { return {Q(v.x()), Q(v.y()), Q(v.z())}; }
QVec operator-(const QVec& a, const QVec& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Q dot(const QVec& a, const QVec& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
QVec cross(const QVec& a, const QVec& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

/// The double nearest to q (ties to the even significand). CGAL's Gmpq::to_double is
/// mpq_get_d, which truncates; it is within one ulp, so the nearest double is among it and
/// its two neighbours.
double nearest_double(const Q& q, bool* exact) {
  const double d = CGAL::to_double(q);
  double best = d;
  Q best_err = CGAL::abs(Q(d) - q);
  for (double c : {std::nextafter(d, -INFINITY), std::nextafter(d, INFINITY)}) {
    const Q err = CGAL::abs(Q(c) - q);
    if (err < best_err) {
      best = c;
      best_err = err;
    } else if (err == best_err) {
      // Tie: keep the candidate with an even significand.
      int eb = 0, ec = 0;
      const double mb = std::frexp(best, &eb), mc = std::frexp(c, &ec);
      const auto odd = [](double m) { return std::fmod(std::ldexp(m, 53), 2.0) != 0.0; };
      if (odd(mb) && !odd(mc)) best = c;
    }
  }
  *exact = (best_err == 0);
  return best;
}

/// Intersects [lo, hi] (lo_set/hi_set false = unbounded) with {t : -h <= f0 + t df <= h}.
/// Returns false when the constraint alone is unsatisfiable (df = 0 and |f0| > h).
bool clip(const Q& f0, const Q& df, const Q& h, Q& lo, Q& hi) {
  if (CGAL::is_zero(df)) return CGAL::abs(f0) <= h;
  Q t1 = (-h - f0) / df, t2 = (h - f0) / df;
  if (t2 < t1) std::swap(t1, t2);
  if (t1 > lo) lo = t1;
  if (t2 < hi) hi = t2;
  return true;
}

}  // namespace

bool exact_tri_tri(const Triangle& a, const Triangle& b) {
  for (const Triangle* t : {&a, &b})
    for (const Vec3& v : *t)
      if (!finite(v)) throw std::domain_error("exact_tri_tri: non-finite coordinate");
  const Shape sa = shape_of(a), sb = shape_of(b);
  return std::visit([](const auto& x, const auto& y) { return intersects(x, y); }, sa, sb);
}

ExactSegmentPlane exact_segment_plane(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2) {
  if (!finite(plane.position) || !finite(plane.normal) || !finite(plane.forward) || !finite(p1) ||
      !finite(p2) || !std::isfinite(plane.half_extents.x()) || !std::isfinite(plane.half_extents.y()))
    throw std::domain_error("exact_segment_plane: non-finite input");

  // A negative half extent leaves no point with |a| <= hx (or |b| <= hy): the rectangle is empty.
  if (plane.half_extents.x() < 0.0 || plane.half_extents.y() < 0.0) return {};

  const QVec P = qvec(plane.position), N = qvec(plane.normal), F = qvec(plane.forward);
  const QVec R = cross(N, F);
  const Q hx(plane.half_extents.x()), hy(plane.half_extents.y());
  const QVec d1 = qvec(p1) - P, d2 = qvec(p2) - P;

  const Q s1 = dot(N, d1), s2 = dot(N, d2);
  const int sg1 = CGAL::sign(s1), sg2 = CGAL::sign(s2);
  if (sg1 * sg2 > 0) return {};  // both strictly on one side (also a degenerate segment off the plane)

  // a(t) = a1 + t (a2 - a1), b(t) likewise: F.(p - P) and R.(p - P) are affine along the segment.
  const Q a1 = dot(F, d1), a2 = dot(F, d2), b1 = dot(R, d1), b2 = dot(R, d2);

  ExactSegmentPlane out;
  Q t;
  if (sg1 == 0 && sg2 == 0) {
    // In the plane: the set of t in [0, 1] inside the rectangle is an interval; take its start.
    Q lo(0), hi(1);
    if (!clip(a1, a2 - a1, hx, lo, hi) || !clip(b1, b2 - b1, hy, lo, hi) || lo > hi) return {};
    t = lo;
  } else {
    t = s1 / (s1 - s2);  // s1 != s2 here
    const Q a = a1 + t * (a2 - a1), b = b1 + t * (b2 - b1);
    if (!(CGAL::abs(a) <= hx && CGAL::abs(b) <= hy)) return {};
  }
  out.hit = true;
  out.t = nearest_double(t, &out.t_is_exact);
  return out;
}

}  // namespace tecido::reference
