// Proofs of contact through a sub-feature (exact_ccd_feature_contact.h). Exact parts: expansions
// of sums of products of two coordinate differences (degree 2 in the input), exact when every
// non-zero coordinate lies in [2^-400, 2^400]: a difference's components are multiples of
// 2^-452 and at most 2^401, so a product's low part (a multiple of 2^-904) neither underflows
// nor does its high part overflow. Strict signs: certified floating point (certified_float.h).
#include "reference/exact_ccd_feature_contact.h"

#include "core/geometry/expansion_arithmetic.h"
#include "reference/certified_float.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace tecido::reference {
namespace {

using namespace certified;

/// An exact sum of at most four products of two coordinate differences.
struct DiffExpansion {
  double c[32];
  int n = 0;
  int sign() const { return expansion::expansion_sign(n, c); }
};

/// a - b, exactly (at most two components).
DiffExpansion exact_difference(double a, double b) {
  DiffExpansion d;
  d.n = expansion::diff_expansion(a, b, d.c);
  return d;
}

/// acc += s a b for differences a, b (s = +1 or -1).
void add_product(DiffExpansion& acc, const DiffExpansion& a, const DiffExpansion& b, int s) {
  double p[8], sum[32];
  const int np = expansion::mul_expansion(a.n, a.c, b.n, b.c, p);
  if (s < 0) expansion::negate(np, p);
  acc.n = expansion::sum_expansion(acc.n, acc.c, np, p, sum);
  std::copy(sum, sum + acc.n, acc.c);
}

/// Whether every non-zero coordinate lies in [2^-400, 2^400] (the expansions are exact).
bool in_exact_range(const CcdQuery& q) {
  for (const auto* x : {&q.x0, &q.x1})
    for (const Vec3& p : *x)
      for (int k = 0; k < 3; ++k) {
        const double a = std::fabs(p[k]);
        if (a != 0 && !(a >= 0x1p-400 && a <= 0x1p400)) return false;
      }
  return true;
}

/// Point i of the query at t = 0 (end 0) or t = 1 (end 1).
const Vec3& end_point(const CcdQuery& q, int i, int end) {
  return (end == 0 ? q.x0 : q.x1)[static_cast<std::size_t>(i)];
}

/// Vertex i meets vertex j at some t in [0, 1]: each coordinate difference d_k(t), linear with
/// end values d_k(0), d_k(1), is identically zero or vanishes at the root d_k(0) / (d_k(0) -
/// d_k(1)); the non-zero ones share their root when their end values are proportional
/// (d_k(0) d_l(1) = d_l(0) d_k(1)), and it lies in [0, 1] when d(0) and d(1) are not of one
/// strict sign.
bool vertices_meet(const CcdQuery& q, int i, int j) {
  for (int k = 0; k < 3; ++k) {  // a difference of one strict sign at both ends never vanishes
    const double a0 = end_point(q, i, 0)[k], b0 = end_point(q, j, 0)[k];
    const double a1 = end_point(q, i, 1)[k], b1 = end_point(q, j, 1)[k];
    if ((a0 < b0 && a1 < b1) || (a0 > b0 && a1 > b1)) return false;
  }
  std::array<std::array<DiffExpansion, 2>, 3> d;
  int first = -1;
  for (int k = 0; k < 3; ++k) {
    for (int end = 0; end < 2; ++end) d[k][end] = exact_difference(end_point(q, i, end)[k], end_point(q, j, end)[k]);
    if (first < 0 && (d[k][0].n != 0 || d[k][1].n != 0)) first = k;
  }
  if (first < 0) return true;  // coincident throughout
  const auto& f = d[static_cast<std::size_t>(first)];
  if (f[0].sign() * f[1].sign() > 0) return false;
  for (int k = first + 1; k < 3; ++k) {
    DiffExpansion cross;
    add_product(cross, f[0], d[k][1], 1);
    add_product(cross, d[k][0], f[1], -1);
    if (cross.sign() != 0) return false;
  }
  return true;
}

/// The time interval [l, r] (doubles) as a certified time.
Fe time_interval(double l, double r) {
  const double m = 0.5 * (l + r);
  return Fe{m, up(std::max(m - l, r - m))};
}

/// The vertex-edge problem p on [u, v], with A = p - u, B = v - u and c = A x B.
class VertexEdge {
 public:
  VertexEdge(const CcdQuery& q, int p, int u, int v) : q_(q), p_(p), u_(u), v_(v) {}

  bool proven() const {
    if (!ranges_meet()) return false;
    int nonzero = -1;
    for (int k = 0; k < 3; ++k) {
      if (identically_zero(k)) continue;
      if (nonzero >= 0) return false;  // two non-zero components: a common root needs exact algebra
      nonzero = k;
    }
    if (nonzero < 0) return collinear_contact();
    return component_root_contact(nonzero);
  }

 private:
  /// Whether, on every axis, the range swept by p meets the range swept by the edge's ends
  /// (exact comparisons; a contact needs it: p(t) lies between u(t) and v(t)).
  bool ranges_meet() const {
    for (int k = 0; k < 3; ++k) {
      double lo = INFINITY, hi = -INFINITY;
      for (int end = 0; end < 2; ++end)
        for (int i : {u_, v_}) {
          lo = std::min(lo, end_point(q_, i, end)[k]);
          hi = std::max(hi, end_point(q_, i, end)[k]);
        }
      const double p0 = end_point(q_, p_, 0)[k], p1 = end_point(q_, p_, 1)[k];
      if (std::max(p0, p1) < lo || std::min(p0, p1) > hi) return false;
    }
    return true;
  }

  /// Component k of c is sum over (i, j, s) of s A_i B_j, (i, j, s) = (k+1, k+2, +1), (k+2, k+1, -1).
  static int axis(int k, int shift) { return (k + shift) % 3; }

  Fe diff(int a, int b, int end, int k) const {
    return exact(end_point(q_, a, end)[k]) - exact(end_point(q_, b, end)[k]);
  }
  DiffExpansion exact_diff(int a, int b, int end, int k) const {
    return exact_difference(end_point(q_, a, end)[k], end_point(q_, b, end)[k]);
  }

  /// Component k's Bernstein coefficient on [0, 1] (times 2 for the middle one): ends (e0, e1)
  /// = (0, 0), (1, 1), or the middle's two cross terms (0, 1) + (1, 0).
  template <class Diff, class Acc>
  void coefficient(int k, int which, Diff d, Acc add) const {
    const int i = axis(k, 1), j = axis(k, 2);
    const int ends[3][2][2] = {{{0, 0}, {0, 0}}, {{0, 1}, {1, 0}}, {{1, 1}, {1, 1}}};
    const int terms = which == 1 ? 2 : 1;
    for (int t = 0; t < terms; ++t) {
      const int ea = ends[which][t][0], eb = ends[which][t][1];
      add(d(p_, u_, ea, i), d(v_, u_, eb, j), 1);
      add(d(p_, u_, ea, j), d(v_, u_, eb, i), -1);
    }
  }

  /// Component k's Bernstein coefficient `which` (times 2 for the middle one), certified.
  Fe float_coefficient(int k, int which) const {
    Fe f;
    coefficient(k, which, [&](int a, int b, int end, int kk) { return diff(a, b, end, kk); },
                [&](Fe x, Fe y, int s) { f = s > 0 ? f + x * y : f - x * y; });
    return f;
  }

  /// The exact sign of component k's Bernstein coefficient `which` (certified float first).
  int coefficient_sign(int k, int which) const {
    if (const int s = sign(float_coefficient(k, which))) return s;
    DiffExpansion e;
    coefficient(k, which, [&](int a, int b, int end, int kk) { return exact_diff(a, b, end, kk); },
                [&](const DiffExpansion& x, const DiffExpansion& y, int s) { add_product(e, x, y, s); });
    return e.sign();
  }

  bool identically_zero(int k) const {
    for (int which = 0; which < 3; ++which)
      if (coefficient_sign(k, which) != 0) return false;
    return true;
  }

  /// The exact sign of (p - u).(p - v) at t = 0 or 1.
  int end_dot_sign(int end) const {
    DiffExpansion e;
    for (int k = 0; k < 3; ++k) add_product(e, exact_diff(p_, u_, end, k), exact_diff(p_, v_, end, k), 1);
    return e.sign();
  }

  std::array<FeV, 3> points_at(Fe t) const {
    auto at = [&](int i) {
      const std::size_t s = static_cast<std::size_t>(i);
      return position_at(q_.x0[s], q_.x1[s], t);
    };
    return {at(p_), at(u_), at(v_)};
  }
  Fe dot_at(Fe t) const {
    const auto x = points_at(t);
    return dot(x[0] - x[1], x[0] - x[2]);
  }
  /// Component k of c at t, from the coordinates it needs only.
  Fe component_at(int k, Fe t) const {
    const int i = axis(k, 1), j = axis(k, 2);
    auto at = [&](int point, int kk) {
      const std::size_t s = static_cast<std::size_t>(point);
      const Fe x0 = exact(q_.x0[s][kk]);
      return x0 + t * (exact(q_.x1[s][kk]) - x0);
    };
    const Fe ui = at(u_, i), uj = at(u_, j);
    const Fe ai = at(p_, i) - ui, aj = at(p_, j) - uj, bi = at(v_, i) - ui, bj = at(v_, j) - uj;
    return ai * bj - aj * bi;
  }

  /// p, u, v collinear throughout: a contact where (p - u).(p - v) <= 0, looked for at t = 0,
  /// 1 (exact) and 1/2 (certified).
  bool collinear_contact() const {
    return end_dot_sign(0) <= 0 || end_dot_sign(1) <= 0 || sign(dot_at(exact(0.5))) < 0;
  }

  /// Only component k is not identically zero.
  bool component_root_contact(int k) const {
    const int at0 = coefficient_sign(k, 0), at1 = coefficient_sign(k, 2);  // c_k(0), c_k(1), exact
    if (at0 == 0 && end_dot_sign(0) <= 0) return true;
    if (at1 == 0 && end_dot_sign(1) <= 0) return true;
    for (double r : approximate_roots(k))
      for (double delta : {0x1p-12, 0x1p-26, 0x1p-40}) {
        const double l = std::max(0.0, r - delta), h = std::min(1.0, r + delta);
        if (!(l < h)) continue;
        const int sl = l == 0 ? at0 : sign(component_at(k, exact(l)));
        const int sh = h == 1 ? at1 : sign(component_at(k, exact(h)));
        if (sl == 0 || sh == 0 || sl == sh) continue;
        if (sign(dot_at(time_interval(l, h))) < 0) return true;  // a root in (l, h), p inside [u, v]
      }
    return false;
  }

  /// Approximations of component k's roots in [0, 1] (from its rounded Bernstein coefficients:
  /// c(t) = b0 (1 - t)^2 + m t (1 - t) + b2 t^2 with m twice the middle one).
  std::array<double, 2> approximate_roots(int k) const {
    const double b0 = float_coefficient(k, 0).v, m = float_coefficient(k, 1).v, b2 = float_coefficient(k, 2).v;
    const double a = b0 - m + b2, b = m - 2 * b0, c0 = b0;  // c(t) = a t^2 + b t + c0
    const double scale = std::fabs(b0) + std::fabs(m) + std::fabs(b2);
    if (std::fabs(a) <= 0x1p-40 * scale) return {b != 0 ? -c0 / b : -1.0, -1.0};
    const double disc = std::max(0.0, b * b - 4 * a * c0);
    const double qq = -0.5 * (b + std::copysign(std::sqrt(disc), b));
    return {qq != 0 ? qq / a : -b / (2 * a), qq != 0 ? c0 / qq : -1.0};
  }

  const CcdQuery& q_;
  int p_, u_, v_;
};

}  // namespace

bool proven_feature_contact(const CcdQuery& q) {
  if (!in_exact_range(q)) return false;
  const bool vf = q.kind == CcdKind::VertexFace;
  // (vertex, edge end, edge end) and (vertex, vertex) pairs of the two primitives.
  static constexpr int kVfEdges[3][3] = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}};
  static constexpr int kEeEdges[4][3] = {{0, 2, 3}, {1, 2, 3}, {2, 0, 1}, {3, 0, 1}};
  static constexpr int kVfVertices[3][2] = {{0, 1}, {0, 2}, {0, 3}};
  static constexpr int kEeVertices[4][2] = {{0, 2}, {0, 3}, {1, 2}, {1, 3}};
  const int n = vf ? 3 : 4;
  for (int i = 0; i < n; ++i) {
    const int* e = vf ? kVfEdges[i] : kEeEdges[i];
    if (VertexEdge(q, e[0], e[1], e[2]).proven()) return true;
  }
  for (int i = 0; i < n; ++i) {
    const int* v = vf ? kVfVertices[i] : kEeVertices[i];
    if (vertices_meet(q, v[0], v[1])) return true;
  }
  return false;
}

}  // namespace tecido::reference
