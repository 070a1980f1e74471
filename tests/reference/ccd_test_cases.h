#pragma once
// Continuous-collision queries whose answers are known by construction, shared by the CCD tests
// (test_exact_ccd.cpp, test_exact_ccd_filter.cpp, test_fcl_ccd.cpp, test_bullet_ccd.cpp).
// Every coordinate is a small dyadic rational (an integer over 512 at most), so every sum and
// product below is exact in double precision and the constructed contacts are real contacts.
#include "core/geometry/ccd/query.h"

#include <array>
#include <cmath>
#include <random>

namespace tecido::reference::ccd_cases {

/// A query and its answer known by construction.
struct Known {
  CcdQuery q;
  bool hit = false;
  double toi = 0.0;  ///< exact (a multiple of 1/8) when hit
};

inline CcdQuery make(CcdKind kind, const std::array<Vec3, 4>& x0, const std::array<Vec3, 4>& x1) {
  CcdQuery q;
  q.kind = kind;
  q.x0 = x0;
  q.x1 = x1;
  return q;
}

/// The query whose points are at `at` at time t and move with velocities v over [0, 1]:
/// x0 = at - t v, x1 = at + (1 - t) v.
inline CcdQuery moving_through(CcdKind kind, double t, const std::array<Vec3, 4>& at, const std::array<Vec3, 4>& v) {
  CcdQuery q;
  q.kind = kind;
  for (std::size_t i = 0; i < 4; ++i) {
    q.x0[i] = at[i] - t * v[i];
    q.x1[i] = at[i] + (1 - t) * v[i];
  }
  return q;
}

/// A vector of integers over 64 in [-range/64, range/64].
inline Vec3 dyadic_vec(std::mt19937& rng, int range = 64) {
  std::uniform_int_distribution<int> d(-range, range);
  return Vec3(d(rng), d(rng), d(rng)) / 64.0;
}

/// Whether the displacement has a non-zero component along each of Bullet's 13 k-DOP directions
/// (bullet_ccd.h: a vertex at rest along one of them is never hit by Bullet).
inline bool generic_for_bullet(const Vec3& d) {
  const double dirs[13][3] = {{1, 0, 0},  {0, 1, 0},  {0, 0, 1}, {1, 1, 0},  {1, 0, 1},  {0, 1, 1},  {1, -1, 0},
                              {1, 0, -1}, {0, 1, -1}, {1, 1, 1}, {1, -1, 1}, {1, 1, -1}, {1, -1, -1}};
  for (const auto& k : dirs)
    if (std::fabs(d.x() * k[0] + d.y() * k[1] + d.z() * k[2]) < 1.0 / 16) return false;
  return true;
}

/// Vertex-face with a rigidly translating triangle. At time t (a multiple of 1/8) the triangle
/// has corners a, b, c and the vertex is at bary[0] a + bary[1] b + bary[2] c (weights summing
/// to 1, multiples of 1/16); the triangle moves with velocity vt, the vertex with vp. The normal
/// N = (b - a) x (c - a) is constant, so the coplanarity cubic is (t' - t) N.(vp - vt), whose
/// only root is t: the answer is a hit at t exactly when every weight is >= 0, a miss otherwise.
/// "Clear" queries (for the floating-point engines) keep |N| and |N.(vp - vt)| large and the
/// vertex's displacement generic along Bullet's directions.
inline Known vf_translation(std::mt19937& rng, double t, const std::array<double, 3>& bary, bool clear = false) {
  for (;;) {
    const Vec3 a = dyadic_vec(rng), b = dyadic_vec(rng), c = dyadic_vec(rng);
    const Vec3 vt = dyadic_vec(rng), vp = dyadic_vec(rng);
    const Vec3 n = (b - a).cross(c - a);
    const double approach = n.dot(vp - vt);
    if (approach == 0) continue;
    if (clear && (n.norm() < 0.5 || std::fabs(approach) < 0.25 * n.norm() || !generic_for_bullet(vp))) continue;
    const Vec3 p = bary[0] * a + bary[1] * b + bary[2] * c;
    Known k;
    k.q = moving_through(CcdKind::VertexFace, t, {p, a, b, c}, {vp, vt, vt, vt});
    k.hit = bary[0] >= 0 && bary[1] >= 0 && bary[2] >= 0;
    k.toi = k.hit ? t : 0.0;
    return k;
  }
}

/// Edge-edge with both edges translating rigidly. At time t the edges a0-a1 and b0-b1 pass through
/// q = a0 + u (a1 - a0) = b0 + v (b1 - b0) (u, v multiples of 1/16); a moves with va, b with vb.
/// m = da x db is constant, so the cubic is (t' - t) m.(vb - va), with the single root t: a hit at t
/// exactly when u and v are in [0, 1].
inline Known ee_translation(std::mt19937& rng, double t, double u, double v, bool clear = false) {
  for (;;) {
    const Vec3 a0 = dyadic_vec(rng), da = dyadic_vec(rng), db = dyadic_vec(rng);
    const Vec3 va = dyadic_vec(rng), vb = dyadic_vec(rng);
    const Vec3 m = da.cross(db);
    const double approach = m.dot(vb - va);
    if (approach == 0) continue;
    if (clear && (da.norm() < 0.5 || db.norm() < 0.5 || m.norm() < 0.25 * da.norm() * db.norm() ||
                  std::fabs(approach) < 0.25 * m.norm()))
      continue;
    const Vec3 q = a0 + u * da, b0 = q - v * db;
    Known k;
    k.q = moving_through(CcdKind::EdgeEdge, t, {a0, a0 + da, b0, b0 + db}, {va, va, vb, vb});
    k.hit = u >= 0 && u <= 1 && v >= 0 && v <= 1;
    k.toi = k.hit ? t : 0.0;
    return k;
  }
}

}  // namespace tecido::reference::ccd_cases
