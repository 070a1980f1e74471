// The vertex-face families of the ccd suite (families.h). Query points: the vertex, then the
// triangle's corners. Each construction's answer is argued beside it; coordinates stay small
// dyadic rationals (constructions.h), so every constructed contact is exact in double precision.
#include "comparisons/suites/ccd/families.h"

#include <cmath>

namespace tecido::suites::ccd {

namespace {

constexpr CcdKind kVF = CcdKind::VertexFace;

/// Vertex and triangle in translation: the corners A, B, C (dyadic, |N| not small, N = (B - A) x
/// (C - A)) move with one velocity vt, the vertex with vp, and at time t the vertex is at
/// w0 A + w1 B + w2 C (w summing to 1). N is constant and the vertex's height over the plane is
/// linear in time with slope N.(vp - vt) != 0, so the only coplanar instant is t: a hit at t
/// exactly when every w >= 0. Mapped by a random dyadic affine map.
KnownQuery vf_through(Rng& r, double t, const std::array<double, 3>& w) {
  for (;;) {
    const Vec3 a = dyadic_vec(r, 64, 64), b = dyadic_vec(r, 64, 64), c = dyadic_vec(r, 64, 64);
    const Vec3 vt = dyadic_vec(r, 64, 64), vp = dyadic_vec(r, 64, 64);
    const Vec3 n = (b - a).cross(c - a);
    if (n.squaredNorm() < 0.0625 || std::fabs(n.dot(vp - vt)) < 0.1 * n.norm()) continue;
    const Vec3 p = w[0] * a + w[1] * b + w[2] * c;
    const CcdQuery q = mapped(moving_through(kVF, t, {p, a, b, c}, {vp, vt, vt, vt}), random_affine(r));
    const bool inside = w[0] >= 0 && w[1] >= 0 && w[2] >= 0;
    return (inside && t >= 0 && t <= 1) ? known_hit(q, t) : known_miss(q);
  }
}

/// Weights w1, w2 in [lo, hi] / 16 and w0 = 1 - w1 - w2.
std::array<double, 3> weights(Rng& r, int lo, int hi) {
  const double w1 = dyadic(r, lo, hi, 16), w2 = dyadic(r, lo, hi, 16);
  return {1.0 - w1 - w2, w1, w2};
}

/// A crossing at a generic time (1/8 .. 7/8) with random weights: about a third inside.
KnownQuery vf_generic(Rng& r) { return vf_through(r, dyadic(r, 1, 7, 8), weights(r, -6, 16)); }

/// The 2-D triangle of the planar constructions: corners with |cross| >= 1/8, and a point
/// strictly inside, (A + B + 2 C) / 4.
struct Tri2 {
  Vec2 a, b, c;
  Vec2 inner() const { return 0.25 * (a + b + 2.0 * c); }
};
Tri2 triangle2(Rng& r) {
  for (;;) {
    Tri2 t{{dyadic(r, -16, 16, 16), dyadic(r, -16, 16, 16)},
           {dyadic(r, -16, 16, 16), dyadic(r, -16, 16, 16)},
           {dyadic(r, -16, 16, 16), dyadic(r, -16, 16, 16)}};
    const Vec2 e = t.b - t.a, f = t.c - t.a;
    if (std::fabs(e.x() * f.y() - e.y() * f.x()) >= 0.125) return t;
  }
}

/// Vertex p0 -> p0 + d and the static 2-D triangle, all moved by a common in-plane velocity and
/// placed in a random plane: coplanar throughout.
CcdQuery planar_query(Rng& r, const Tri2& t, const Vec2& p0, const Vec2& d) {
  const PlaneFrame f = random_plane(r);
  const Vec2 c(dyadic(r, -32, 32, 32), dyadic(r, -32, 32, 32));
  const std::array<Vec2, 4> x0 = {p0, t.a, t.b, t.c};
  const std::array<Vec2, 4> x1 = {p0 + d + c, t.a + c, t.b + c, t.c + c};
  CcdQuery q;
  q.kind = kVF;
  for (int i = 0; i < 4; ++i) {
    q.x0[i] = f.at(x0[i].x(), x0[i].y());
    q.x1[i] = f.at(x1[i].x(), x1[i].y());
  }
  return q;
}

}  // namespace

void vf_random(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out) {
  random_motion(kVF, r, s.small_motion, count, out);
}

void vf_crossing(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) out.push_back(vf_generic(r));
}

/// Spikes through cracks and holes: the vertex passes exactly through an edge of the triangle
/// (a crack between two triangles: the triangle across the edge is hit too) or a corner, or just
/// outside an edge or a corner by 1/128 .. 1/32 in barycentric weight (a hole): a miss.
void vf_spike(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  const std::size_t end = out.size() + count;
  while (out.size() < end) {
    const double t = dyadic(r, 1, 7, 8), l = dyadic(r, 1, 15, 16), h = dyadic(r, 1, 4, 128);
    switch (r.below(4)) {
      case 0: {  // through edge BC, then the same motion against the triangle (D, B, C) across it
        const KnownQuery kq = vf_through(r, t, {0.0, l, 1.0 - l});
        out.push_back(kq);
        if (out.size() == end) break;
        CcdQuery across = kq.q;
        for (auto* x : {&across.x0, &across.x1}) (*x)[1] = (*x)[2] + (*x)[3] - (*x)[1];
        out.push_back(known_hit(across, t));
        break;
      }
      case 1: out.push_back(vf_through(r, t, {1.0, 0.0, 0.0})); break;                   // through corner A
      case 2: out.push_back(vf_through(r, t, {-2 * h, l + h, 1.0 - l + h})); break;        // past edge BC
      default: out.push_back(vf_through(r, t, {1.0 + 2 * h, -h, -h})); break;             // past corner A
    }
  }
}

/// Sliding (coplanar throughout): in a random plane, the vertex slides inside the triangle
/// (a hit at 0), enters it through edge AB at time t (toward an inner point, so the entry point
/// on AB is the first contact: a hit at t), or slides parallel to AB on the far side (a miss).
void vf_sliding(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const Tri2 t = triangle2(r);
    const Vec2 q = t.a + dyadic(r, 1, 15, 16) * (t.b - t.a), in = t.inner();
    switch (k % 3) {
      case 0: {
        const Vec2 d(dyadic(r, -32, 32, 32), dyadic(r, -32, 32, 32));
        out.push_back(known_hit(planar_query(r, t, in, d), 0.0));
        break;
      }
      case 1: {
        const double tc = dyadic(r, 0, 8, 8);
        const Vec2 d = dyadic(r, 1, 4, 2) * (in - q);
        out.push_back(known_hit(planar_query(r, t, q - tc * d, d), tc));
        break;
      }
      default: {
        const double gap = r.below(2) ? std::ldexp(1.0, -20) : dyadic(r, 1, 16, 16);
        out.push_back(known_miss(planar_query(r, t, q + gap * (q - in), dyadic(r, -4, 4, 2) * (t.b - t.a))));
        break;
      }
    }
  }
}

/// Parallel motion: the triangle in the plane z = 0 and the vertex at a height h != 0 (down to
/// 2^-30) all move parallel to the plane (plus one common 3-D velocity, which changes nothing):
/// the vertex never reaches the plane, a miss. Mapped by a random affine map.
void vf_parallel(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  const double heights[] = {1.0, 0.25, 1.0 / 64, std::ldexp(1.0, -30)};
  for (std::size_t k = 0; k < count; ++k) {
    const Tri2 t = triangle2(r);
    const double h = (r.below(2) ? -1.0 : 1.0) * heights[r.below(4)];
    const Vec3 common = dyadic_vec(r, 32, 32);
    auto flat = [&r] { return Vec3(dyadic(r, -32, 32, 32), dyadic(r, -32, 32, 32), 0.0); };
    const Vec3 vt = flat(), vp = flat();
    const Vec2 p = t.inner() + Vec2(dyadic(r, -16, 16, 16), dyadic(r, -16, 16, 16));
    CcdQuery q;
    q.kind = kVF;
    q.x0 = {Vec3(p.x(), p.y(), h), Vec3(t.a.x(), t.a.y(), 0), Vec3(t.b.x(), t.b.y(), 0), Vec3(t.c.x(), t.c.y(), 0)};
    q.x1 = {q.x0[0] + vp + common, q.x0[1] + vt + common, q.x0[2] + vt + common, q.x0[3] + vt + common};
    out.push_back(known_miss(mapped(q, random_affine(r))));
  }
}

/// Degenerate faces: zero-area triangles (the third corner at the midpoint of the others, a
/// corner repeated, the third corner beyond the second on their line, all three at one point),
/// whose point set is a segment H0-H1 or a point. The triangle translates, the vertex moves with
/// another velocity not parallel to the segment, and at time t it is at H0 + sigma (H1 - H0): its
/// line crosses the segment's line once, so a hit at t exactly when 0 <= sigma <= 1. For the point
/// triangle the vertex passes through it, or beside it by an offset not along its relative motion.
void vf_degenerate(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count;) {
    const double t = dyadic(r, 0, 8, 8), sigma = dyadic(r, -4, 20, 16);
    const Vec3 s0 = dyadic_vec(r, 64, 64), s1 = dyadic_vec(r, 64, 64);
    const Vec3 vt = dyadic_vec(r, 64, 64), vp = dyadic_vec(r, 64, 64), w = vp - vt;
    std::array<Vec3, 3> tri;
    Vec3 h0 = s0, h1 = s1;
    switch (k % 4) {
      case 0: tri = {s0, s1, 0.5 * (s0 + s1)}; break;
      case 1: tri = {s0, s1, s0}; break;
      case 2: tri = {s0, s1, 2.0 * s1 - s0}, h1 = 2.0 * s1 - s0; break;
      default: tri = {s0, s0, s0}, h1 = s0; break;
    }
    if (k % 4 != 3 && (w.cross(h1 - h0).squaredNorm() < 1e-3 || h1 == h0)) continue;
    if (k % 4 == 3 && w.squaredNorm() < 1e-3) continue;
    Vec3 p = h0 + sigma * (h1 - h0);
    bool hit = sigma >= 0 && sigma <= 1;
    if (k % 4 == 3) {
      const Vec3 off = r.below(2) ? Vec3::Zero() : dyadic_vec(r, 8, 64);
      if (off != Vec3::Zero() && off.cross(w).squaredNorm() == 0) continue;
      p = s0 + off, hit = off == Vec3::Zero();
    }
    const CcdQuery q = mapped(moving_through(kVF, t, {p, tri[0], tri[1], tri[2]}, {vp, vt, vt, vt}), random_affine(r));
    out.push_back(hit ? known_hit(q, t) : known_miss(q));
    ++k;
  }
}

/// Contact at the ends of the step: the translation construction with the vertex inside the
/// triangle at t = 0 or t = 1 (hits), or inside at t just before 0 or just after 1 (misses), or
/// outside at t = 0 or 1 (misses).
void vf_endpoints(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  const double times[] = {0.0, 1.0, -1.0 / 8, -1.0 / 64, 1.0 + 1.0 / 64, 1.0 + 1.0 / 8};
  for (std::size_t k = 0; k < count; ++k) {
    const bool inside = k % 4 != 3;
    const double t = inside ? times[r.below(6)] : static_cast<double>(r.below(2));
    out.push_back(vf_through(r, t, inside ? weights(r, 1, 7) : std::array<double, 3>{-0.0625, 0.5, 0.5625}));
  }
}

/// Near misses by a few ulps: the triangle (a, 0, 0), (b, 0, 0), (c, h, 0) and the vertex going
/// from z = 1 to z = -1, crossing z = 0 at t = 1/2 at (x, y, 0) with x well inside [a, b] and
/// y = s k 2^-52, s in {-1, 0, 1}: a hit at 1/2 exactly when y >= 0 (edge y = 0 closed). Only
/// motions along x and z are added (exact) and the axes are permuted and flipped (exact).
void vf_near_miss(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const double a = dyadic(r, -64, -16, 64), b = dyadic(r, 16, 64, 64), c = dyadic(r, -16, 16, 64);
    const double h = dyadic(r, 16, 64, 64), x = dyadic(r, -8, 8, 64), dx = dyadic(r, -32, 32, 64);
    const int sign = static_cast<int>(r.below(3)) - 1;
    const double y = sign * std::ldexp(s.near_miss_ulps[r.below(s.near_miss_ulps.size())], -52);
    const double dy = dyadic(r, -32, 32, 64);
    const Vec3 common(dyadic(r, -32, 32, 32), 0.0, dyadic(r, -32, 32, 32));
    CcdQuery q;
    q.kind = kVF;
    q.x0 = {Vec3(x - dx, y - dy, 1.0), Vec3(a, 0, 0), Vec3(b, 0, 0), Vec3(c, h, 0)};
    q.x1 = {Vec3(x + dx, y + dy, -1.0) + common, q.x0[1] + common, q.x0[2] + common, q.x0[3] + common};
    q = permuted_axes(q, r);
    out.push_back(sign >= 0 ? known_hit(q, 0.5) : known_miss(q));
  }
}

/// Huge and tiny scales: generic crossings multiplied by 2^e (e from the settings, in turn), or
/// moved by +-2^k along each axis; both exact, so the answers stand.
void vf_scale(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out) {
  rescaled_queries(r, &vf_generic, s.scale_exponents, s.offset_exponents, count, out);
}

}  // namespace tecido::suites::ccd
