// The certified floating-point filter of the exact CCD referee, in the certified arithmetic of
// certified_float.h.
#include "reference/exact_ccd_filter.h"

#include "reference/certified_float.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace tecido::reference {
namespace {

using namespace certified;

/// The four points at time t (an interval or a double).
std::array<FeV, 4> positions(const CcdQuery& q, Fe t) {
  std::array<FeV, 4> out;
  for (std::size_t i = 0; i < 4; ++i) out[i] = position_at(q.x0[i], q.x1[i], t);
  return out;
}

/// The three vectors whose determinant is the coplanarity cubic f: vertex-face (b - a, c - a,
/// p - a) with p = x[0]; edge-edge (a1 - a0, b1 - b0, b0 - a0).
std::array<FeV, 3> cubic_vectors(const CcdQuery& q, const std::array<FeV, 4>& x) {
  if (q.kind == CcdKind::VertexFace) return {x[2] - x[1], x[3] - x[1], x[0] - x[1]};
  return {x[1] - x[0], x[3] - x[2], x[2] - x[0]};
}

/// +1: the closed primitives touch at every t of `t` at which they are coplanar; -1: they touch
/// at none of them; 0: not proven. Vertex-face: with n = (b-a) x (c-a), the vertex is in the
/// closed triangle iff ((v-u) x (p-u)) . n >= 0 for the three edges u -> v (a zero normal makes
/// all three zero, so a proven sign implies n != 0). Edge-edge: with m = da x db, w = b0 - a0,
/// the crossing parameters are (w x db).m / m.m and (w x da).m / m.m, both in [0, 1].
int touches_on(const CcdQuery& q, Fe t) {
  const auto x = positions(q, t);
  std::array<Fe, 4> s;
  int count = 3;
  if (q.kind == CcdKind::VertexFace) {
    const FeV &p = x[0], &a = x[1], &b = x[2], &c = x[3];
    const FeV n = cross(b - a, c - a);
    s = {dot(cross(b - a, p - a), n), dot(cross(c - b, p - b), n), dot(cross(a - c, p - c), n), Fe{}};
  } else {
    const FeV da = x[1] - x[0], db = x[3] - x[2], w = x[2] - x[0];
    const FeV m = cross(da, db);
    const Fe mm = dot(m, m), nu = dot(cross(w, db), m), nv = dot(cross(w, da), m);
    s = {nu, mm - nu, nv, mm - nv};
    count = 4;
  }
  int positive = 0;
  for (int i = 0; i < count; ++i) {
    const int sg = sign(s[static_cast<std::size_t>(i)]);
    if (sg < 0) return -1;
    positive += sg > 0;
  }
  return positive == count ? 1 : 0;
}

/// Whether the swept bounding boxes of the two primitives are disjoint (exact comparisons).
bool boxes_disjoint(const CcdQuery& q) {
  const int first_b = q.kind == CcdKind::VertexFace ? 1 : 2;
  for (int k = 0; k < 3; ++k) {
    double lo[2] = {INFINITY, INFINITY}, hi[2] = {-INFINITY, -INFINITY};
    for (int i = 0; i < 4; ++i)
      for (const auto* x : {&q.x0, &q.x1}) {
        const int side = i < first_b ? 0 : 1;
        lo[side] = std::min(lo[side], (*x)[i][k]);
        hi[side] = std::max(hi[side], (*x)[i][k]);
      }
    if (hi[0] < lo[1] || hi[1] < lo[0]) return true;
  }
  return false;
}

/// The cubic's Bernstein coefficients on [0, 1] (multilinear expansion of the determinant).
std::array<Fe, 4> bernstein(const CcdQuery& q) {
  const auto u0 = cubic_vectors(q, positions(q, exact(0)));
  const auto u1 = cubic_vectors(q, positions(q, exact(1)));
  auto d = [&](int i, int j, int k) { return det((i ? u1 : u0)[0], (j ? u1 : u0)[1], (k ? u1 : u0)[2]); };
  return {d(0, 0, 0), third(d(1, 0, 0) + d(0, 1, 0) + d(0, 0, 1)), third(d(0, 1, 1) + d(1, 0, 1) + d(1, 1, 0)),
          d(1, 1, 1)};
}

/// The cubic at t = t1 + t2 (doubles in [0, 1]) from its Bernstein coefficients on [0, 1]
/// (de Casteljau: x (1 - t) + y t = x + (y - x) t1 + (y - x) t2).
Fe cubic_at(const std::array<Fe, 4>& b, double t1, double t2 = 0) {
  auto mix = [&](Fe x, Fe y) {
    const Fe d = y - x;
    Fe r = x + d * exact(t1);
    return t2 == 0 ? r : r + d * exact(t2);
  };
  const Fe b01 = mix(b[0], b[1]), b12 = mix(b[1], b[2]), b23 = mix(b[2], b[3]);
  return mix(mix(b01, b12), mix(b12, b23));
}

bool one_strict_sign(const std::array<Fe, 4>& b) {
  int s = sign(b[0]);
  if (s == 0) return false;
  for (const Fe& x : b)
    if (sign(x) != s) return false;
  return true;
}

/// An interval (l, r) holding exactly one simple root of the cubic; sign_l = sign of f(l).
struct RootInterval {
  double l, r;
  int sign_l;
};

/// Appends, left to right, intervals isolating the cubic's roots in (l, r) from its Bernstein
/// coefficients there. False when it cannot prove the isolation within the depth limit.
bool isolate(const std::array<Fe, 4>& b, double l, double r, int depth, std::vector<RootInterval>& out) {
  if (one_strict_sign(b)) return true;
  const int s0 = sign(b[0]), s3 = sign(b[3]);
  const int d0 = sign(b[1] - b[0]), d1 = sign(b[2] - b[1]), d2 = sign(b[3] - b[2]);
  if (s0 != 0 && s3 != 0 && d0 != 0 && d0 == d1 && d1 == d2) {  // strictly monotone
    if (s0 != s3) out.push_back({l, r, s0});
    return true;
  }
  if (depth == 12) return false;
  // de Casteljau at s = 7/16 of the interval: the left part's coefficients are b0, b01, b012,
  // b0123, the right's b0123, b123, b23, b3. Not at 1/2, where hand-made roots (1/2, 1/4, ...)
  // would land on a split point and leave its sign unproven; 7/16 keeps every split point a
  // double (a multiple of 2^-48 after 12 levels).
  const Fe s{7.0 / 16, 0}, s1{9.0 / 16, 0};
  auto mix = [&](Fe x, Fe y) { return x * s1 + y * s; };
  const Fe b01 = mix(b[0], b[1]), b12 = mix(b[1], b[2]), b23 = mix(b[2], b[3]);
  const Fe b012 = mix(b01, b12), b123 = mix(b12, b23), mid = mix(b012, b123);
  const double m = l + (r - l) * (7.0 / 16);  // exact (see above)
  return isolate({b[0], b01, b012, mid}, l, m, depth + 1, out) && isolate({mid, b123, b23, b[3]}, m, r, depth + 1, out);
}

/// The interval (l, r) as a time: midpoint and a radius covering both ends.
Fe interval(double l, double r) {
  const double m = 0.5 * (l + r);
  return Fe{m, up(std::max(m - l, r - m))};
}

/// Narrows `ri` at a double strictly inside it where the cubic's sign is proven (tried at 7/16
/// and 9/16 of the interval, off the dyadic points where hand-made roots sit); false if neither.
bool narrow(const std::array<Fe, 4>& b, RootInterval& ri) {
  for (double f : {7.0 / 16, 9.0 / 16}) {
    const double m = ri.l + (ri.r - ri.l) * f;
    if (!(ri.l < m && m < ri.r)) continue;
    const int s = sign(cubic_at(b, m));
    if (s == 0) continue;
    (s == ri.sign_l ? ri.l : ri.r) = m;
    return true;
  }
  return false;
}

/// An approximation of the root in `ri` from the cubic's rounded Bernstein coefficients
/// (regula falsi, Illinois variant; plain doubles, certifies nothing).
double approximate_root(const std::array<Fe, 4>& b, const RootInterval& ri) {
  auto f = [&](double t) {
    const double s = 1 - t;
    const double b01 = b[0].v * s + b[1].v * t, b12 = b[1].v * s + b[2].v * t, b23 = b[2].v * s + b[3].v * t;
    return (b01 * s + b12 * t) * s + (b12 * s + b23 * t) * t;
  };
  double l = ri.l, r = ri.r, fl = f(l), fr = f(r);
  int side = 0;
  for (int i = 0; i < 60 && l < r; ++i) {
    double m = (fl == fr) ? 0.5 * (l + r) : r - fr * (r - l) / (fr - fl);
    if (!(l < m && m < r)) m = 0.5 * (l + r);  // a step onto an end: bisect instead
    if (!(l < m && m < r)) break;
    const double fm = f(m);
    if (fm == 0) return m;
    if ((fm > 0) == (fl > 0)) {
      l = m, fl = fm;
      if (side == -1) fr *= 0.5;
      side = -1;
    } else {
      r = m, fr = fm;
      if (side == 1) fl *= 0.5;
      side = 1;
    }
  }
  return std::fabs(f(l)) <= std::fabs(f(r)) ? l : r;
}

/// Narrows `ri` in one step to a few ulps around its root, when the cubic's signs prove the
/// root is there (tried at distances 2^-50 to 2^-16 of an approximation); false if not.
bool jump_to_root(const std::array<Fe, 4>& b, RootInterval& ri) {
  const double t = approximate_root(b, ri);
  for (double delta : {0x1p-50, 0x1p-47, 0x1p-44, 0x1p-40, 0x1p-32, 0x1p-24, 0x1p-16}) {
    const double l = t - delta, r = t + delta;
    if (!(ri.l < l && r < ri.r)) continue;
    if (sign(cubic_at(b, l)) == ri.sign_l && sign(cubic_at(b, r)) == -ri.sign_l) {
      ri.l = l;
      ri.r = r;
      return true;
    }
  }
  return false;
}

/// Narrows `ri` until touches_on decides it: first in one jump close to the root, then by at
/// most kMaxNarrowings sign-proven splits; 0 when it cannot.
int decide_root(const CcdQuery& q, const std::array<Fe, 4>& b, RootInterval& ri) {
  constexpr int kMaxNarrowings = 99;
  jump_to_root(b, ri);
  for (int iter = 0;; ++iter) {
    const int verdict = touches_on(q, interval(ri.l, ri.r));
    if (verdict != 0 || iter == kMaxNarrowings || !narrow(b, ri)) return verdict;
  }
}

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}
double from_bits(std::uint64_t b) {
  double x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

/// The verdict for a hit whose time is the root in `ri`: the root narrowed between doubles by
/// bisection on their bit patterns (monotone for non-negative doubles) while the cubic's sign is
/// proven; once they are adjacent, rounded by the sign at their exact midpoint l + (r - l)/2.
CcdFilterVerdict hit_verdict(const std::array<Fe, 4>& b, const RootInterval& ri) {
  CcdFilterVerdict v;
  v.kind = CcdFilterVerdict::Kind::Hit;
  v.sign_lo = ri.sign_l;
  std::uint64_t lo = bits(ri.l), hi = bits(ri.r);
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    const int s = sign(cubic_at(b, from_bits(mid)));
    if (s == 0) break;
    (s == ri.sign_l ? lo : hi) = mid;
  }
  v.lo = from_bits(lo);
  v.hi = from_bits(hi);
  const double h = 0.5 * (v.hi - v.lo);
  if (hi - lo == 1 && h != 0 && 2 * h == v.hi - v.lo) {  // a double midpoint (not subnormal spacing)
    const int s = sign(cubic_at(b, v.lo, h));
    if (s != 0) v.toi = s == ri.sign_l ? v.hi : v.lo;  // same sign as at lo: the root is past the midpoint
  }
  return v;
}

}  // namespace

CcdFilterVerdict certified_float_ccd(const CcdQuery& q) {
  CcdFilterVerdict miss;
  miss.kind = CcdFilterVerdict::Kind::Miss;
  if (boxes_disjoint(q)) return miss;
  const std::array<Fe, 4> b = bernstein(q);
  std::vector<RootInterval> roots;
  if (!isolate(b, 0.0, 1.0, 0, roots)) return {};
  for (RootInterval& ri : roots) {
    const int verdict = decide_root(q, b, ri);
    if (verdict == 0) return {};
    if (verdict > 0) return hit_verdict(b, ri);
  }
  return miss;
}

}  // namespace tecido::reference
