#include "core/geometry/tri_tri_intersect.h"

#include "core/geometry/orient_predicates.h"

#include "core/platform/simd_level.h"
#include "core/simd/dispatch.h"
#include "core/simd/widths.h"

#include <algorithm>
#include <cmath>

namespace tecido {
namespace {

// Guigue & Devillers write [a,b,c,d] = (d-a).((b-a)x(c-a)) = -orient3d_sign(a,b,c,d).
inline int gd_bracket(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return -orient3d_sign(a, b, c, d);
}

// ---------------------------------------------------------------------------------------
// Sides of three points against the oriented plane of a triangle t: signs of [t0,t1,t2,x].
// The cross product n = (t1-t0)x(t2-t0) and the permanent's coefficients are computed once
// per triangle. (x-t0).n has exactly the shape of Shewchuk's orient3d filter (nine rounded
// differences, six products, ...), so his bound A * permanent holds barring underflow.
// Underflow: each product is then off by at most 2^-1075 more; the three w_i n_i products are
// covered by kUnderflowPad (2^-1000), the products inside n_i (multiplied by |w_i|) by padding
// each coefficient with 2^-900 and A by 2^-100: when the pad survives the addition (coefficient
// < 2^-847) it adds at least A 2^-901 |w_i|; when it is absorbed, 2^-100 * 2^-847 |w_i| does;
// both far above 2 * 2^-1075 |w_i|. The pads are large enough that no intermediate of a flat
// (axis-aligned) configuration is subnormal: subnormal arithmetic is slow on most CPUs. The
// three filters run without branches; a point the filter cannot decide goes to the exact
// predicate.
constexpr double kCoefPad = 0x1p-900;
constexpr double kErrBound = detail::kOrient3dErrBoundA + 0x1p-100;

// The filter, written once for every width (tri_tri_plane.inl; the build has -ffp-contract=off,
// so no width fuses a multiply-add and the wide copies round as the scalar one).
#define TECIDO_SIMD_KERNEL "core/geometry/tri_tri_plane.inl"
#include "core/simd/for_each_width.inl"

inline simd1::V3<simd1::Lanes> point(const Vec3& p) { return {p[0], p[1], p[2]}; }

void plane_sides(const Triangle& t, const Triangle& x, int s[3]) {
  using S = simd1::Lanes;
  const simd1::PlaneFilter<S> f = simd1::plane_filter<S>(point(t[0]), point(t[1]), point(t[2]));
  const double ux = f.u.x, uy = f.u.y, uz = f.u.z, vx = f.v.x, vy = f.v.y, vz = f.v.z;
  bool decided[3];
  for (int i = 0; i < 3; ++i) {
    double det, errbound;
    simd1::side_filter<S>(f, point(x[i]), det, errbound);
    s[i] = (det > errbound) - (-det > errbound);
    decided[i] = std::fabs(det) > errbound;  // false for NaN too
  }
  if (__builtin_expect(!(decided[0] & decided[1] & decided[2]), 0)) {
    for (int i = 0; i < 3; ++i) {
      if (decided[i]) continue;
      // Exactly zero without the exact path when the four points share one coordinate (an
      // axis-aligned plane, e.g. a flat cloth at rest): a difference of doubles is 0 exactly
      // when they are equal, and a zero column makes the determinant exactly 0.
      const double wx = x[i][0] - t[0][0], wy = x[i][1] - t[0][1], wz = x[i][2] - t[0][2];
      if ((ux == 0 && vx == 0 && wx == 0) || (uy == 0 && vy == 0 && wy == 0) || (uz == 0 && vz == 0 && wz == 0)) {
        s[i] = 0;
      } else {
        s[i] = -detail::orient3d_sign_exact(t[0], t[1], t[2], x[i]);
      }
    }
  }
}

// ---------------------------------------------------------------------------------------
// Guigue-Devillers canonical form: the vertex alone on its side of the other plane.
// For the three sides s (not all zero, not all equal and nonzero), the index of the lone
// vertex and the side (+1/-1) it is to be treated as being on, so that the other two vertices
// are on the opposite side or on the plane: a vertex strictly on a side is lone when the
// others are not on that side; a vertex on the plane is lone when the other two are strictly
// on one side (it is then treated as being on the other). Encoded as index + 3 * (side < 0),
// looked up by 9 (s0 + 1) + 3 (s1 + 1) + (s2 + 1); -1 marks the excluded sign patterns.
struct LoneTable {
  signed char code[27];
  constexpr LoneTable() : code() {
    for (int c = 0; c < 27; ++c) {
      const int s[3] = {c / 9 - 1, (c / 3) % 3 - 1, c % 3 - 1};
      const int pos = (s[0] > 0) + (s[1] > 0) + (s[2] > 0);
      const int neg = (s[0] < 0) + (s[1] < 0) + (s[2] < 0);
      int want = 0, side = 0;
      if (pos == 1) {
        want = side = 1;
      } else if (neg == 1) {
        want = side = -1;
      } else if (pos + neg == 2) {
        side = pos == 2 ? -1 : 1;
      }
      code[c] = -1;
      if (side == 0) continue;  // all zero, or all strictly on one side
      const int i = s[0] == want ? 0 : (s[1] == want ? 1 : 2);
      code[c] = static_cast<signed char>(i + 3 * (side < 0));
    }
  }
};
constexpr LoneTable kLone;

inline int lone_code(const int s[3]) { return kLone.code[9 * (s[0] + 1) + 3 * (s[1] + 1) + (s[2] + 1)]; }

// ---------------------------------------------------------------------------------------
// Exact low-dimensional helpers for coplanar and degenerate configurations.

/// orient2d of the projection that drops axis k; its sign is the sign of the k-th component
/// of (b-a)x(c-a), exactly.
inline int orient_drop(const Vec3& a, const Vec3& b, const Vec3& c, int k) {
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  return orient2d_sign(a[i], a[j], b[i], b[j], c[i], c[j]);
}

/// An axis k along which the normal of the (non-collinear) triangle abc is nonzero, trying the
/// dominant component of the rounded normal first; -1 when a, b, c are collinear.
int normal_axis(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 n = (b - a).cross(c - a);
  const double ax = std::fabs(n[0]), ay = std::fabs(n[1]), az = std::fabs(n[2]);
  int order[3];
  order[0] = ax >= ay ? (ax >= az ? 0 : 2) : (ay >= az ? 1 : 2);
  order[1] = (order[0] + 1) % 3;
  order[2] = (order[0] + 2) % 3;
  for (int k : order)
    if (orient_drop(a, b, c, k) != 0) return k;
  return -1;
}

struct P2 {
  double x, y;
};

inline P2 project(const Vec3& v, int k) { return {v[(k + 1) % 3], v[(k + 2) % 3]}; }

inline int orient2(const P2& a, const P2& b, const P2& c) {
  return orient2d_sign(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Closed 2-D segments ab and cd (each may be a single point) share a point.
bool segments_meet_2d(const P2& a, const P2& b, const P2& c, const P2& d) {
  const int o1 = orient2(a, b, c), o2 = orient2(a, b, d);
  if (o1 * o2 > 0) return false;
  const int o3 = orient2(c, d, a), o4 = orient2(c, d, b);
  if (o3 * o4 > 0) return false;
  if (o1 == 0 && o2 == 0 && o3 == 0 && o4 == 0) {
    // Collinear (or points): the boxes overlap on both axes iff the segments overlap.
    return std::max(std::min(a.x, b.x), std::min(c.x, d.x)) <=
               std::min(std::max(a.x, b.x), std::max(c.x, d.x)) &&
           std::max(std::min(a.y, b.y), std::min(c.y, d.y)) <=
               std::min(std::max(a.y, b.y), std::max(c.y, d.y));
  }
  return true;
}

/// p lies in the closed non-degenerate 2-D triangle abc (either orientation).
bool point_in_triangle_2d(const P2& p, const P2& a, const P2& b, const P2& c) {
  const int o1 = orient2(a, b, p), o2 = orient2(b, c, p), o3 = orient2(c, a, p);
  const bool has_neg = o1 < 0 || o2 < 0 || o3 < 0;
  const bool has_pos = o1 > 0 || o2 > 0 || o3 > 0;
  return !(has_neg && has_pos);
}

/// Closed segment ab meets the closed non-degenerate 2-D triangle t.
bool segment_triangle_2d(const P2& a, const P2& b, const P2 (&t)[3]) {
  if (point_in_triangle_2d(a, t[0], t[1], t[2])) return true;
  for (int i = 0; i < 3; ++i)
    if (segments_meet_2d(a, b, t[i], t[(i + 1) % 3])) return true;
  return false;
}

/// Coplanar non-degenerate triangles, k an axis along which their common normal is nonzero.
/// Separating-axis theorem in the plane: two closed triangles are disjoint iff the three
/// vertices of one lie strictly outside the line of some edge of the other (disjoint compact
/// convex sets are strictly separated by a line parallel to an edge of one of them, and that
/// edge's own line then separates too). Every side is an exact orient2d sign, so the answer is
/// exact; no intersection point is constructed.
bool coplanar_triangles(const Triangle& p, const Triangle& q, int k) {
  const P2 a[3] = {project(p[0], k), project(p[1], k), project(p[2], k)};
  const P2 b[3] = {project(q[0], k), project(q[1], k), project(q[2], k)};
  // Both are non-degenerate in this projection (their normals are parallel, component k != 0).
  const int oa = orient2(a[0], a[1], a[2]);
  const int ob = orient2(b[0], b[1], b[2]);
  auto separated_by_edge_of = [](const P2 (&t)[3], int orientation, const P2 (&u)[3]) {
    for (int i = 0; i < 3; ++i) {
      const P2& e0 = t[i];
      const P2& e1 = t[(i + 1) % 3];
      if (orient2(e0, e1, u[0]) == -orientation && orient2(e0, e1, u[1]) == -orientation &&
          orient2(e0, e1, u[2]) == -orientation)
        return true;
    }
    return false;
  };
  return !separated_by_edge_of(a, oa, b) && !separated_by_edge_of(b, ob, a);
}

/// What a closed triangle covers: itself, a segment (collinear vertices) or a point.
struct Simplex {
  int dim;        // 2 triangle, 1 segment, 0 point
  int axis;       // dim 2: axis along which the normal is nonzero; dim 1: an axis along
                  // which the segment's end points differ
  Vec3 v[3];      // dim 2: the vertices; dim 1: the end points v[0], v[1]; dim 0: v[0]
};

Simplex classify(const Triangle& t) {
  Simplex s;
  s.v[0] = t[0];
  s.v[1] = t[1];
  s.v[2] = t[2];
  s.axis = normal_axis(t[0], t[1], t[2]);
  if (s.axis >= 0) {
    s.dim = 2;
    return s;
  }
  // Collinear: the hull is the segment between the extreme vertices along any axis on
  // which the vertices are not all equal.
  for (int k = 0; k < 3; ++k) {
    if (t[0][k] == t[1][k] && t[1][k] == t[2][k]) continue;
    int lo = 0, hi = 0;
    for (int i = 1; i < 3; ++i) {
      if (t[i][k] < t[lo][k]) lo = i;
      if (t[i][k] > t[hi][k]) hi = i;
    }
    s.dim = 1;
    s.axis = k;
    s.v[0] = t[lo];
    s.v[1] = t[hi];
    return s;
  }
  s.dim = 0;
  return s;
}

/// Closed segment ab (a != b) meets the closed non-degenerate triangle t (normal axis k).
bool segment_triangle(const Vec3& a, const Vec3& b, const Triangle& t, int k) {
  const int da = gd_bracket(t[0], t[1], t[2], a);
  const int db = gd_bracket(t[0], t[1], t[2], b);
  if (da * db > 0) return false;
  if (da == 0 && db == 0) {
    const P2 tt[3] = {project(t[0], k), project(t[1], k), project(t[2], k)};
    return segment_triangle_2d(project(a, k), project(b, k), tt);
  }
  // The segment meets the plane in exactly one point; it lies in the closed triangle iff
  // the line ab does not pass strictly on opposite sides of two edges (Plucker signs).
  const int e0 = orient3d_sign(a, b, t[0], t[1]);
  const int e1 = orient3d_sign(a, b, t[1], t[2]);
  const int e2 = orient3d_sign(a, b, t[2], t[0]);
  const bool has_neg = e0 < 0 || e1 < 0 || e2 < 0;
  const bool has_pos = e0 > 0 || e1 > 0 || e2 > 0;
  return !(has_neg && has_pos);
}

/// Point x lies in the closed non-degenerate triangle t (normal axis k).
bool point_triangle(const Vec3& x, const Triangle& t, int k) {
  if (orient3d_sign(t[0], t[1], t[2], x) != 0) return false;
  return point_in_triangle_2d(project(x, k), project(t[0], k), project(t[1], k),
                              project(t[2], k));
}

/// Closed segments ab and cd (a != b, c != d) share a point.
bool segment_segment(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  if (orient3d_sign(a, b, c, d) != 0) return false;
  // Coplanar: project along an axis the projection is injective on a common plane.
  int k = normal_axis(a, b, c);
  if (k < 0) k = normal_axis(a, b, d);
  if (k >= 0) {
    return segments_meet_2d(project(a, k), project(b, k), project(c, k), project(d, k));
  }
  // All four points collinear: compare intervals along an axis where a and b differ.
  int m = 0;
  while (a[m] == b[m]) ++m;
  return std::max(std::min(a[m], b[m]), std::min(c[m], d[m])) <=
         std::min(std::max(a[m], b[m]), std::max(c[m], d[m]));
}

/// Point x lies on the closed segment ab (a != b, m an axis on which they differ).
bool point_segment(const Vec3& x, const Vec3& a, const Vec3& b, int m) {
  for (int k = 0; k < 3; ++k)
    if (orient_drop(a, b, x, k) != 0) return false;  // not collinear
  return std::min(a[m], b[m]) <= x[m] && x[m] <= std::max(a[m], b[m]);
}

bool simplices_meet(const Simplex& s, const Simplex& t) {
  if (s.dim < t.dim) return simplices_meet(t, s);
  const Triangle st{s.v[0], s.v[1], s.v[2]};
  switch (s.dim * 3 + t.dim) {
    case 8:  // triangle, triangle: coplanar (the caller saw all sides zero)
      return coplanar_triangles(st, Triangle{t.v[0], t.v[1], t.v[2]}, s.axis);
    case 7:
      return segment_triangle(t.v[0], t.v[1], st, s.axis);
    case 6:
      return point_triangle(t.v[0], st, s.axis);
    case 4:
      return segment_segment(s.v[0], s.v[1], t.v[0], t.v[1]);
    case 3:
      return point_segment(t.v[0], s.v[0], s.v[1], s.axis);
    default:
      return s.v[0] == t.v[0];
  }
}

/// Exact closed axis-aligned boxes overlap.
bool boxes_overlap(const Triangle& p, const Triangle& q) {
  for (int k = 0; k < 3; ++k) {
    const double plo = std::min({p[0][k], p[1][k], p[2][k]});
    const double phi = std::max({p[0][k], p[1][k], p[2][k]});
    const double qlo = std::min({q[0][k], q[1][k], q[2][k]});
    const double qhi = std::max({q[0][k], q[1][k], q[2][k]});
    if (phi < qlo || qhi < plo) return false;
  }
  return true;
}

/// The rare branch (common only for flat cloth): every vertex of `on` lies on the plane of
/// `base` (exactly). Either the pair is coplanar or one triangle is degenerate (its "plane" is
/// every plane through it). Fast path: base is non-degenerate with normal axis k, so `on` lies
/// in base's plane, and `on` is non-degenerate iff its projection along k is (one orient2d
/// instead of classifying both).
bool coplanar_or_degenerate(const Triangle& on, const Triangle& base) {
  if (!boxes_overlap(on, base)) return false;
  const int k = normal_axis(base[0], base[1], base[2]);
  if (k >= 0 && orient_drop(on[0], on[1], on[2], k) != 0) return coplanar_triangles(base, on, k);
  return simplices_meet(classify(on), classify(base));
}

}  // namespace

bool tri_tri_intersect(const Triangle& p, const Triangle& q) {
  // 1. Sides of p's vertices against q's plane; reject when all strictly on one side.
  int sp[3];
  plane_sides(q, p, sp);
  const int sum_p = sp[0] + sp[1] + sp[2];
  if (sum_p == 3 || sum_p == -3) return false;  // all three strictly on one side
  // All of p on q's plane: a coplanar pair or a degenerate q (or p); step 3 below.
  if ((sp[0] | sp[1] | sp[2]) == 0) return coplanar_or_degenerate(/*on=*/p, /*base=*/q);
  // 2. The same for q against p's plane.
  int sq[3];
  plane_sides(p, q, sq);
  const int sum_q = sq[0] + sq[1] + sq[2];
  if (sum_q == 3 || sum_q == -3) return false;
  // 3. A triangle entirely on the other's plane: coplanar pair or a degenerate triangle.
  //    Otherwise some side is nonzero on each triangle, which certifies both non-degenerate.
  if ((sq[0] | sq[1] | sq[2]) == 0) {
    return coplanar_or_degenerate(/*on=*/q, /*base=*/p);
  }
  // 4. Canonical form (Guigue & Devillers, section 3): p1 alone on its side of q's plane with
  //    [q1,q2,q3,p1] > 0, q1 alone with [p1,p2,p3,q1] > 0; circular shifts keep the brackets,
  //    swapping the last two vertices of a triangle flips its plane.
  static constexpr int kNext[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  const int cp = lone_code(sp), cq = lone_code(sq);
  const int ip = cp % 3, iq = cq % 3;
  const int flip_q = cp / 3;  // p1 on the negative side of q's plane: swap q2 and q3
  const int flip_p = cq / 3;  // q1 on the negative side of p's plane: swap p2 and p3
  const Vec3& p1 = p[ip];
  const Vec3& p2 = p[kNext[ip][flip_p]];
  const Vec3& p3 = p[kNext[ip][1 - flip_p]];
  const Vec3& q1 = q[iq];
  const Vec3& q2 = q[kNext[iq][flip_q]];
  const Vec3& q3 = q[kNext[iq][1 - flip_q]];
  // 5. The intervals cut by the two triangles on the planes' common line overlap iff
  //    [p1,p2,q1,q2] <= 0 and [p1,p3,q3,q1] <= 0 (both evaluated: no short-circuit branch).
  const int b1 = gd_bracket(p1, p2, q1, q2);
  const int b2 = gd_bracket(p1, p3, q3, q1);
  return (b1 <= 0) & (b2 <= 0);
}

bool tri_tri_reject8_available() {
  static const bool ok = simd::width_available(8);  // the CPU has AVX-512F and TECIDO_SIMD allows it
  return ok;
}

unsigned tri_tri_reject8(const double* x, const int (&pv)[3][8], const int (&qv)[3][8]) {
  using Kernel = unsigned (*)(const double*, const int (&)[3][8], const int (&)[3][8]);
#if TECIDO_SIMD_X86
  static const Kernel k = simd::pick<Kernel>(simd::widest_width(1, 8), &simd1::reject8<simd1::Lanes>,
                                             &simd2::reject8<simd2::Lanes>, &simd4::reject8<simd4::Lanes>,
                                             &simd8::reject8<simd8::Lanes>);
#else
  static const Kernel k = simd::pick<Kernel>(simd::widest_width(1, 8), &simd1::reject8<simd1::Lanes>,
                                             &simd2::reject8<simd2::Lanes>, nullptr, nullptr);
#endif
  return k(x, pv, qv);
}

}  // namespace tecido
