// The edge-edge families of the ccd suite (families.h). Query points: a0, a1, b0, b1. Each
// construction's answer is argued beside it; coordinates stay small dyadic rationals
// (constructions.h), so every constructed contact is exact in double precision.
#include "comparisons/suites/ccd/families.h"

#include <cmath>

namespace tecido::suites::ccd {

namespace {

constexpr CcdKind kEE = CcdKind::EdgeEdge;

/// Two edges in translation: directions ea, eb (not nearly parallel), edge a moving with va and
/// b with vb, and at time t the point P = a0 + s ea = b0 + u eb common to both lines. The
/// coplanarity determinant det(ea, eb, b0 - a0) is linear in time with slope
/// (vb - va).(ea x eb) != 0, so the lines meet only at t: a hit at t exactly when s and u are in
/// [0, 1] (and t in [0, 1]). Mapped by a random dyadic affine map.
KnownQuery ee_through(Rng& r, double t, double s, double u) {
  for (;;) {
    const Vec3 p = dyadic_vec(r, 64, 64), ea = dyadic_vec(r, 64, 64), eb = dyadic_vec(r, 64, 64);
    const Vec3 va = dyadic_vec(r, 64, 64), vb = dyadic_vec(r, 64, 64);
    const Vec3 n = ea.cross(eb);
    if (n.squaredNorm() < 0.0625 || std::fabs(n.dot(vb - va)) < 0.1 * n.norm()) continue;
    const Vec3 a0 = p - s * ea, b0 = p - u * eb;
    const CcdQuery q = mapped(moving_through(kEE, t, {a0, a0 + ea, b0, b0 + eb}, {va, va, vb, vb}), random_affine(r));
    const bool on_both = s >= 0 && s <= 1 && u >= 0 && u <= 1;
    return (on_both && t >= 0 && t <= 1) ? known_hit(q, t) : known_miss(q);
  }
}

/// A crossing at a generic time with s, u in [-1/4, 5/4]: a little over half on both segments.
KnownQuery ee_generic(Rng& r) {
  return ee_through(r, dyadic(r, 1, 7, 8), dyadic(r, -4, 20, 16), dyadic(r, -4, 20, 16));
}

/// A dyadic direction near `axis` (|e| >= 1/4), in the plane z = 0 when `flat`.
Vec3 line_direction(Rng& r, const Vec3& axis, bool flat = false) {
  for (;;) {
    Vec3 e = dyadic_vec(r, 16, 16) + axis;
    if (flat) e.z() = 0;
    if (e.squaredNorm() >= 0.0625) return e;
  }
}

/// A direction not parallel to e (dyadic).
Vec3 transverse(Rng& r, const Vec3& e) {
  for (;;) {
    const Vec3 f = dyadic_vec(r, 16, 16);
    if (f.cross(e).squaredNorm() >= 0.0625) return f;
  }
}

/// The query with every point also moved by one common velocity (nothing changes) and mapped.
CcdQuery finish(Rng& r, const std::array<Vec3, 4>& x0, const std::array<Vec3, 4>& x1) {
  const Vec3 common = dyadic_vec(r, 32, 32);
  CcdQuery q;
  q.kind = kEE;
  q.x0 = x0;
  for (int i = 0; i < 4; ++i) q.x1[i] = x1[i] + common;
  return mapped(q, random_affine(r));
}

}  // namespace

void ee_random(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out) {
  random_motion(kEE, r, s.small_motion, count, out);
}

void ee_crossing(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) out.push_back(ee_generic(r));
}

/// Spikes through cracks and holes: the lines meet exactly at an end of one edge (s or u in
/// {0, 1}) or at ends of both: hits; or just past an end, by 1/64 .. 1/16 of the edge: misses.
void ee_crack(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const double t = dyadic(r, 1, 7, 8), in = dyadic(r, 1, 15, 16), end = static_cast<double>(r.below(2));
    const double past = end == 0 ? -dyadic(r, 1, 4, 64) : 1 + dyadic(r, 1, 4, 64);
    switch (k % 4) {
      case 0: out.push_back(ee_through(r, t, end, in)); break;
      case 1: out.push_back(ee_through(r, t, in, end)); break;
      case 2: out.push_back(ee_through(r, t, end, static_cast<double>(r.below(2)))); break;
      default: out.push_back(r.below(2) ? ee_through(r, t, past, in) : ee_through(r, t, in, past)); break;
    }
  }
}

/// Edges sliding on edges, on the line L = o + lambda e: a = [0, La] at rest; b = [g, g + Lb]
/// sliding toward it along L, its front reaching a's end at t (a hit at t, touching at 0 when
/// t = 0); b overlapping a at 0 and sliding (a hit at 0); b crossing a's interior at 0 and
/// sliding along e (a hit at 0); b on a parallel line at a distance, sliding (a miss).
void ee_sliding(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 o = dyadic_vec(r, 32, 32), e = line_direction(r, Vec3(1, 0, 0));
    const double la = dyadic(r, 4, 16, 16), lb = dyadic(r, 4, 16, 16), v = dyadic(r, 1, 16, 16);
    auto on_l = [&](double lambda) { return Vec3(o + lambda * e); };
    const std::array<Vec3, 4> rest = {on_l(0), on_l(la), Vec3::Zero(), Vec3::Zero()};
    std::array<Vec3, 4> x0 = rest, x1 = rest;
    switch (k % 4) {
      case 0: {
        const double t = dyadic(r, 0, 8, 8), g = la + v * t;
        x0[2] = on_l(g), x0[3] = on_l(g + lb), x1[2] = on_l(g - v), x1[3] = on_l(g + lb - v);
        out.push_back(known_hit(finish(r, x0, x1), t));
        break;
      }
      case 1: {
        const double g = dyadic(r, -16, 16, 16) * la;
        x0[2] = on_l(g), x0[3] = on_l(g + lb), x1[2] = on_l(g + v), x1[3] = on_l(g + lb + v);
        if (g + lb < 0) x0[3] = on_l(0), x1[3] = on_l(v);  // keep b's end on a at t = 0
        out.push_back(known_hit(finish(r, x0, x1), 0.0));
        break;
      }
      case 2: {
        const Vec3 f = transverse(r, e), p = on_l(dyadic(r, 1, 15, 16) * la);
        const double u = dyadic(r, 0, 16, 16);
        x0[2] = p - u * f, x0[3] = p + (1 - u) * f, x1[2] = x0[2] + v * e, x1[3] = x0[3] + v * e;
        out.push_back(known_hit(finish(r, x0, x1), 0.0));
        break;
      }
      default: {
        const double gaps[] = {0.5, 1.0 / 64, std::ldexp(1.0, -20)};
        const Vec3 off = gaps[r.below(3)] * transverse(r, e);
        const double g = dyadic(r, -16, 16, 16);
        x0[2] = on_l(g) + off, x0[3] = on_l(g + lb) + off, x1[2] = x0[2] + v * e, x1[3] = x0[3] + v * e;
        out.push_back(known_miss(finish(r, x0, x1)));
        break;
      }
    }
  }
}

/// Wedges: a wedge's ridge coming down onto an edge parallel to it. a = [0, La] on the line L at
/// rest; b = [g, g + Lb] on the parallel line L + (tau - t) f, which reaches L at tau. Before and
/// after tau the lines are disjoint, so a hit at tau exactly when [g, g + Lb] meets [0, La]
/// (overlapping, or touching end to end), otherwise a miss.
void ee_wedge(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 o = dyadic_vec(r, 32, 32), e = line_direction(r, Vec3(0, 1, 0)), f = transverse(r, e);
    const double la = dyadic(r, 4, 16, 16), lb = dyadic(r, 4, 16, 16), tau = dyadic(r, 0, 8, 8);
    double g;
    switch (k % 4) {
      case 0: g = dyadic(r, -15, 15, 16) * la; break;                     // mostly overlapping
      case 1: g = r.below(2) ? la : -lb; break;                           // touching end to end
      case 2: g = la + dyadic(r, 1, 16, 64); break;                       // past a's far end
      default: g = -lb - std::ldexp(1.0, -static_cast<int>(r.below(3)) * 10 - 6); break;  // short of a's start
    }
    auto at = [&](double lambda, double time) { return Vec3(o + lambda * e + (tau - time) * f); };
    const std::array<Vec3, 4> x0 = {o, o + la * e, at(g, 0), at(g + lb, 0)};
    const std::array<Vec3, 4> x1 = {o, o + la * e, at(g, 1), at(g + lb, 1)};
    const bool hit = g <= la && g + lb >= 0;
    const CcdQuery q = finish(r, x0, x1);
    out.push_back(hit ? known_hit(q, tau) : known_miss(q));
  }
}

/// Coplanar motion: in a random plane, a = [(xa0, 0), (xa1, 0)] at rest and b moving straight
/// down (velocity (0, -vy)) with its lower end at (xb, yb): the lower end reaches the line y = 0
/// at t = yb / vy, a hit at t when xb is in [xa0, xa1]; with b leaning away from a (its other end
/// farther out) and xb outside, b never meets a: a miss. Also b parallel to a (both ends at
/// height yb): a hit at t exactly when the x ranges meet.
void ee_coplanar(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const double xa0 = dyadic(r, -16, -2, 16), xa1 = dyadic(r, 2, 16, 16), t = dyadic(r, 0, 8, 8);
    const double vy = dyadic(r, 1, 16, 16), yb = t * vy, dy = dyadic(r, 1, 16, 16);
    double xb = dyadic(r, -24, 24, 16), dx = dyadic(r, -16, 16, 16);
    bool hit = xb >= xa0 && xb <= xa1;
    if (k % 3 == 2) {  // parallel to a
      if (dx < 0) xb += dx, dx = -dx;
      hit = xb <= xa1 && xb + dx >= xa0;
    } else if (!hit) {
      dx = xb > xa1 ? std::fabs(dx) : -std::fabs(dx);  // lean away
    }
    const double top = k % 3 == 2 ? yb : yb + dy;
    const PlaneFrame f = random_plane(r);
    const Vec2 c(dyadic(r, -32, 32, 32), dyadic(r, -32, 32, 32));
    CcdQuery q;
    q.kind = kEE;
    q.x0 = {f.at(xa0, 0), f.at(xa1, 0), f.at(xb, yb), f.at(xb + dx, top)};
    q.x1 = {f.at(xa0 + c.x(), c.y()), f.at(xa1 + c.x(), c.y()), f.at(xb + c.x(), yb - vy + c.y()),
            f.at(xb + dx + c.x(), top - vy + c.y())};
    out.push_back(hit ? known_hit(q, t) : known_miss(q));
  }
}

/// Parallel motion, all misses: b on a line parallel to a at a distance, sliding along it; or a
/// in the plane z = 0 and b in the plane z = h != 0, each moving parallel to the planes.
void ee_parallel(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  const double heights[] = {1.0, 0.25, 1.0 / 64, std::ldexp(1.0, -30)};
  for (std::size_t k = 0; k < count; ++k) {
    const Vec3 up(0, 0, (r.below(2) ? -1.0 : 1.0) * heights[r.below(4)]);
    auto flat = [&r] { return Vec3(dyadic(r, -32, 32, 32), dyadic(r, -32, 32, 32), 0.0); };
    std::array<Vec3, 4> x0, x1;
    if (k % 2 == 0) {  // parallel lines, b sliding along them
      const Vec3 e = line_direction(r, Vec3(1, 0, 0), true), o = flat();
      const double g = dyadic(r, -16, 16, 16), v = dyadic(r, -16, 16, 16);
      x0 = {o, o + e, o + g * e + up, o + (g + 1) * e + up};
      x1 = {x0[0], x0[1], x0[2] + v * e, x0[3] + v * e};
    } else {  // parallel planes, each edge moving in its own
      const Vec3 va = flat(), vb = flat();
      x0 = {flat(), flat(), flat() + up, flat() + up};
      x1 = {x0[0] + va, x0[1] + va, x0[2] + vb, x0[3] + vb};
    }
    out.push_back(known_miss(finish(r, x0, x1)));
  }
}

/// Degenerate edges: a zero-length edge (a point) whose line of relative motion crosses the other
/// edge's line once, at time t, at parameter sigma of that edge: a hit at t exactly when sigma is
/// in [0, 1]; two zero-length edges meeting at t, or passing beside each other by an offset not
/// along their relative motion (a miss).
void ee_degenerate(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count;) {
    const double t = dyadic(r, 0, 8, 8), sigma = dyadic(r, -4, 20, 16);
    const Vec3 b0 = dyadic_vec(r, 64, 64), eb = dyadic_vec(r, 64, 64);
    const Vec3 va = dyadic_vec(r, 64, 64), vb = dyadic_vec(r, 64, 64), w = va - vb;
    bool hit;
    std::array<Vec3, 4> at;
    if (k % 2 == 0) {  // a point against a segment
      if (w.cross(eb).squaredNorm() < 1e-3) continue;
      const Vec3 p = b0 + sigma * eb;
      at = {p, p, b0, b0 + eb};
      hit = sigma >= 0 && sigma <= 1;
    } else {  // two points
      const Vec3 off = r.below(2) ? Vec3::Zero() : dyadic_vec(r, 8, 64);
      if (w.squaredNorm() < 1e-3 || (off != Vec3::Zero() && off.cross(w).squaredNorm() == 0)) continue;
      at = {b0 + off, b0 + off, b0, b0};
      hit = off == Vec3::Zero();
    }
    const CcdQuery q = mapped(moving_through(kEE, t, at, {va, va, vb, vb}), random_affine(r));
    out.push_back(hit ? known_hit(q, t) : known_miss(q));
    ++k;
  }
}

/// Contact at the ends of the step: crossings of the edges' interiors at t = 0 or 1 (hits), at t
/// just before 0 or after 1 (misses), and crossings outside the edges at t = 0 or 1 (misses).
void ee_endpoints(Rng& r, const Settings&, std::size_t count, std::vector<KnownQuery>& out) {
  const double times[] = {0.0, 1.0, -1.0 / 8, -1.0 / 64, 1.0 + 1.0 / 64, 1.0 + 1.0 / 8};
  for (std::size_t k = 0; k < count; ++k) {
    const bool inside = k % 4 != 3;
    const double t = inside ? times[r.below(6)] : static_cast<double>(r.below(2));
    out.push_back(ee_through(r, t, inside ? dyadic(r, 1, 15, 16) : -0.0625, dyadic(r, 1, 15, 16)));
  }
}

/// Near misses by a few ulps: a = [(-1, 0, 0), (1, 0, 0)] at rest; b, moving from z = 1 to
/// z = -1 and crossing z = 0 at t = 1/2, either spans y in [-1/2, 1/2] at x = 1 + k 2^-52 (a miss,
/// past a's end), x = 1 (a hit at the end), x = 1 - k 2^-52 (a hit); or spans y in [s k 2^-52, 1]
/// at an interior x (a hit when s <= 0). Only motions along x and z are added (exact) and the axes
/// are permuted and flipped.
void ee_near_miss(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    const double eps = std::ldexp(s.near_miss_ulps[r.below(s.near_miss_ulps.size())], -52);
    const int sign = static_cast<int>(r.below(3)) - 1;
    const double dz = dyadic(r, -32, 32, 64);
    const Vec3 common(dyadic(r, -32, 32, 32), 0.0, dyadic(r, -32, 32, 32));
    CcdQuery q;
    q.kind = kEE;
    bool hit;
    if (k % 2 == 0) {  // past (or at) a's end
      const double x = 1.0 + sign * eps, dx = dyadic(r, -16, 16, 64);
      q.x0 = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(x - dx, -0.5, 1 + dz), Vec3(x - dx, 0.5, 1 - dz)};
      q.x1 = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(x + dx, -0.5, -1 - dz), Vec3(x + dx, 0.5, -1 + dz)};
      hit = sign <= 0;
    } else {  // b's end just above or below a
      const double x = dyadic(r, -32, 32, 64), y = sign * eps;
      q.x0 = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(x, y, 1), Vec3(x, 1, 1)};
      q.x1 = {Vec3(-1, 0, 0), Vec3(1, 0, 0), Vec3(x, y, -1), Vec3(x, 1, -1)};
      hit = sign <= 0;
    }
    for (Vec3& p : q.x1) p += common;
    q = permuted_axes(q, r);
    out.push_back(hit ? known_hit(q, 0.5) : known_miss(q));
  }
}

/// Huge and tiny scales: generic crossings multiplied by 2^e (e from the settings, in turn), or
/// moved by +-2^k along each axis; both exact, so the answers stand.
void ee_scale(Rng& r, const Settings& s, std::size_t count, std::vector<KnownQuery>& out) {
  rescaled_queries(r, &ee_generic, s.scale_exponents, s.offset_exponents, count, out);
}

}  // namespace tecido::suites::ccd
