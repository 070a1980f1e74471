#include "comparisons/suites/tritri/families.h"

#include <cmath>

namespace tecido::suites::tritri {

namespace {

/// A point with small integer coordinates in [-span, span]: sums and products of a few are exact.
Vec3 lattice(Rng& r, int span) {
  auto c = [&]() { return static_cast<double>(r.below(2 * span + 1)) - span; };
  const double x = c(), y = c();
  return Vec3(x, y, c());
}

/// A non-degenerate triangle of lattice points.
Triangle lattice_triangle(Rng& r, int span) {
  for (;;) {
    const Vec3 p = lattice(r, span), q = lattice(r, span);
    const Triangle t{p, q, lattice(r, span)};
    if ((t[1] - t[0]).cross(t[2] - t[0]).squaredNorm() > 0) return t;
  }
}

Triangle unit_cube_triangle(Rng& r) {
  const Vec3 p = r.in_box(0, 1), q = r.in_box(0, 1);
  return {p, q, r.in_box(0, 1)};
}

/// A triangle with two random corners and the third on (exactly, one time in four) or within
/// 1e-15 .. 1e-5 of the segment between them.
Triangle sliver(Rng& r) {
  const Vec3 s = r.in_box(0, 1), e = r.in_box(0, 1);
  const double eps = r.below(4) == 0 ? 0.0 : std::pow(10.0, r.uniform(-15, -5));
  const double t = r.uniform(0, 1);
  return Triangle{s, e, s + t * (e - s) + eps * r.unit_vector()};
}

}  // namespace

/// Random pairs: six points uniform in the unit cube.
io::TriPair random_pair(Rng& r, long) {
  io::TriPair p;
  p.a = unit_cube_triangle(r);
  p.b = unit_cube_triangle(r);
  return p;
}

/// b within 1e-16 .. 1e-6 of a's plane (per vertex, either side).
io::TriPair near_coplanar_pair(Rng& r, long) {
  io::TriPair p;
  p.a = unit_cube_triangle(r);
  const Vec3 n = (p.a[1] - p.a[0]).cross(p.a[2] - p.a[0]).normalized();
  const Vec3 u = (p.a[1] - p.a[0]).normalized(), v = n.cross(u);
  for (auto& q : p.b) {
    const double s = r.uniform(-0.5, 1.2), t = r.uniform(-0.5, 1.2);
    const double h = std::pow(10.0, r.uniform(-16, -6));
    q = p.a[0] + s * u + t * v + h * (r.below(2) ? 1.0 : -1.0) * n;
  }
  return p;
}

/// Exactly coplanar: integer combinations of two integer vectors from an integer origin.
io::TriPair coplanar_pair(Rng& r, long) {
  Vec3 o, u, v;
  do {
    o = lattice(r, 8);
    u = lattice(r, 3);
    v = lattice(r, 3);
  } while (u.cross(v).squaredNorm() == 0);
  auto pt = [&]() {
    const double s = static_cast<double>(r.below(9)) - 4;
    return o + s * u + (static_cast<double>(r.below(9)) - 4) * v;
  };
  io::TriPair p;
  for (auto& q : p.a) q = pt();
  for (auto& q : p.b) q = pt();
  return p;
}

/// A vertex of b exactly on a's closed face (a dyadic barycentric point of a lattice triangle).
io::TriPair touch_vertex_pair(Rng& r, long) {
  io::TriPair p;
  p.a = lattice_triangle(r, 6);
  // Barycentric weights in quarters with w0 + w1 <= 1: the point is on the closed face, exactly.
  const double w0 = std::ldexp(static_cast<double>(r.below(5)), -2);
  const double w1 = std::ldexp(static_cast<double>(r.below(5 - static_cast<int>(w0 * 4))), -2);
  const Vec3 on = p.a[0] + w1 * (p.a[1] - p.a[0]) + w0 * (p.a[2] - p.a[0]);
  const Vec3 n = (p.a[1] - p.a[0]).cross(p.a[2] - p.a[0]).normalized();
  const double side = r.below(2) ? 1.0 : -1.0;  // the rest of b above, below or (shifted) across a's plane
  Vec3 rest[2];
  for (Vec3& q : rest) {  // one draw after the other: the order of evaluation is fixed
    const double h = r.uniform(0.5, 3);
    q = on + side * n * h + lattice(r, 2);
  }
  p.b = {on, rest[0], rest[1]};
  return p;
}

/// An edge of b passes exactly through the midpoint of an edge of a.
io::TriPair touch_edge_pair(Rng& r, long) {
  io::TriPair p;
  p.a = lattice_triangle(r, 6);
  const int e = static_cast<int>(r.below(3));
  const Vec3 m = 0.5 * (p.a[e] + p.a[(e + 1) % 3]);  // exact: lattice points
  const Vec3 d = lattice(r, 3);
  p.b = {m - d, m + d, m + lattice(r, 4)};  // m is the midpoint of b's edge b0 b1
  if ((p.b[1] - p.b[0]).cross(p.b[2] - p.b[0]).squaredNorm() == 0) p.b[2] += Vec3(1, 2, 3);
  return p;
}

/// b's first vertex is one of a's vertices.
io::TriPair shared_vertex_pair(Rng& r, long) {
  io::TriPair p;
  for (auto& q : p.a) q = r.in_box(-1, 1);
  const Vec3 shared = p.a[r.below(3)], b1 = r.in_box(-1, 1);
  p.b = {shared, b1, r.in_box(-1, 1)};
  return p;
}

/// a nearly or exactly collinear; b a sliver too or a random triangle.
io::TriPair sliver_pair(Rng& r, long) {
  io::TriPair p;
  p.a = sliver(r);
  p.b = r.below(2) ? sliver(r) : unit_cube_triangle(r);
  return p;
}

/// Unit-size random pairs shifted 10^(3 + k mod 6) from the origin.
io::TriPair offset_pair(Rng& r, long k) {
  io::TriPair p;
  const Vec3 shift = std::pow(10.0, 3 + static_cast<double>(k % 6)) * r.unit_vector();
  for (auto& q : p.a) q = shift + r.in_box(0, 1);
  for (auto& q : p.b) q = shift + r.in_box(0, 1);
  return p;
}

const std::vector<Family>& families() {
  static const std::vector<Family> table = {
      {"random", "six points uniform in the unit cube", &random_pair, true},
      {"near-coplanar", "b within 1e-16 .. 1e-6 of a's plane", &near_coplanar_pair},
      {"coplanar", "a and b exactly coplanar (lattice points)", &coplanar_pair},
      {"touch-vertex", "a vertex of b exactly on a's closed face", &touch_vertex_pair},
      {"touch-edge", "an edge of b exactly through the midpoint of an edge of a", &touch_edge_pair},
      {"shared-vertex", "b shares a vertex with a", &shared_vertex_pair},
      {"sliver", "nearly or exactly collinear triangles", &sliver_pair},
      {"offset", "unit-size pairs 10^3 .. 10^8 from the origin", &offset_pair},
  };
  return table;
}

io::TriPair family_pair(std::uint64_t seed, std::size_t f, const Family& family, long k) {
  return agreement::family_case(family, Rng(substream(substream(seed, 1000 + f), static_cast<std::uint64_t>(k))), k);
}

}  // namespace tecido::suites::tritri
