#pragma once
// Constructions with known answers for the continuous collision tests (test_ccd_vertex_face.cpp,
// test_ccd_edge_edge.cpp): contacts built at a chosen time and point, misses separated by a
// moving plane at all times, and the transformations (scaling, translation, time reversal)
// under which the answer must not change.
#include "core/geometry/ccd/query.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

namespace tecido::ccd_test {

inline CcdQuery make(CcdKind kind, const std::array<Vec3, 4>& x0, const std::array<Vec3, 4>& x1) {
  CcdQuery q;
  q.kind = kind;
  q.x0 = x0;
  q.x1 = x1;
  return q;
}

/// The query's scale L of CcdSettings: the largest coordinate of its difference vectors X, Y,
/// Z at t = 0 and t = 1 (ccd/system.h).
inline double query_scale(const CcdQuery& q) {
  const bool vf = q.kind == CcdKind::VertexFace;
  // (minuend, subtrahend) of X, Y, Z.
  const int pairs[2][3][2] = {{{2, 1}, {3, 1}, {0, 1}}, {{1, 0}, {2, 3}, {2, 0}}};
  double l = 0.0;
  for (const auto* x : {&q.x0, &q.x1})
    for (const auto& pr : pairs[vf ? 0 : 1])
      l = std::max(l, ((*x)[pr[0]] - (*x)[pr[1]]).cwiseAbs().maxCoeff());
  return l;
}

/// Every point mapped to s x + offset (contact and time of impact do not change).
inline CcdQuery transformed(const CcdQuery& q, double s, const Vec3& offset) {
  CcdQuery r = q;
  for (auto* x : {&r.x0, &r.x1})
    for (Vec3& p : *x) p = s * p + offset;
  return r;
}

/// The motion run backwards: contact at t becomes contact at 1 - t.
inline CcdQuery time_reversed(const CcdQuery& q) {
  CcdQuery r = q;
  std::swap(r.x0, r.x1);
  return r;
}

/// Points that pass through `at` at time ts with velocities vel: x0 = at - ts vel,
/// x1 = at + (1 - ts) vel.
inline CcdQuery through(CcdKind kind, const std::array<Vec3, 4>& at, const std::array<Vec3, 4>& vel, double ts) {
  CcdQuery q;
  q.kind = kind;
  for (int i = 0; i < 4; ++i) {
    q.x0[i] = at[i] - ts * vel[i];
    q.x1[i] = at[i] + (1.0 - ts) * vel[i];
  }
  return q;
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : g_(seed) {}
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(g_); }
  Vec3 point(double r) {
    const double x = uniform(-r, r), y = uniform(-r, r), z = uniform(-r, r);
    return Vec3(x, y, z);
  }
  Vec3 unit() {
    for (;;) {
      const Vec3 p = point(1.0);
      if (p.norm() > 0.1 && p.norm() <= 1.0) return p.normalized();
    }
  }
  int index(int n) { return std::uniform_int_distribution<int>(0, n - 1)(g_); }

 private:
  std::mt19937_64 g_;
};

/// A contact built at time ts: vertex-face (vertex at barycentric (u, v) well inside the face)
/// or edge-edge (crossing at parameters well inside both segments), each primitive
/// translating rigidly, the relative motion crossing the plane of contact transversally
/// (normal speed 1 to 2, sizes below about 2, normals at least 0.2 |X| |Y|). With perturb = 0
/// the coplanarity function is linear in t, so ts is the only coplanar instant: the first
/// contact, up to the rounding of building the points (far below 1e-12). With perturb <= 0.02
/// every point's velocity also gets its own perturbation up to `perturb` per axis (the
/// primitives rotate and deform): the rotation terms of the cubic's slope at ts stay below a
/// third of the normal term, so the crossing stays transversal and there is still a contact
/// within rounding of ts at a point inside, but maybe an earlier one too.
inline CcdQuery built_contact(CcdKind kind, Rng& r, double ts, double perturb = 0.0) {
  std::array<Vec3, 4> at, vel;
  Vec3 n;
  if (kind == CcdKind::VertexFace) {
    Vec3 x, y;
    do {
      at[1] = r.point(1.0);
      x = r.point(1.0);
      y = r.point(1.0);
      n = x.cross(y);
    } while (n.norm() < 0.2 * x.norm() * y.norm());  // no sliver faces here
    at[2] = at[1] + x;
    at[3] = at[1] + y;
    const double u = r.uniform(0.05, 0.85);
    const double v = r.uniform(0.05, 0.9 - u);
    at[0] = at[1] + u * x + v * y;
  } else {
    Vec3 ea, eb;
    do {
      ea = r.point(1.0);
      eb = r.point(1.0);
      n = ea.cross(eb);
    } while (n.norm() < 0.2 * ea.norm() * eb.norm());
    const Vec3 c = r.point(1.0);
    const double u = r.uniform(0.05, 0.95), v = r.uniform(0.05, 0.95);
    at = {c - u * ea, c + (1.0 - u) * ea, c - v * eb, c + (1.0 - v) * eb};
  }
  const Vec3 va = r.point(1.0), nh = n.normalized();
  Vec3 tangential = r.point(0.3);
  tangential -= tangential.dot(nh) * nh;
  const Vec3 rel = tangential + (r.uniform(0.0, 1.0) < 0.5 ? -1.0 : 1.0) * r.uniform(1.0, 2.0) * nh;
  const Vec3 vb = va + rel;
  vel = kind == CcdKind::VertexFace ? std::array<Vec3, 4>{vb, va, va, va} : std::array<Vec3, 4>{va, va, vb, vb};
  if (perturb > 0)
    for (Vec3& v : vel) v += r.point(perturb);
  return through(kind, at, vel, ts);
}

/// Points on either side of a moving plane n . x = o0 + t o1 at every t in [0, 1]: the first
/// primitive's points at signed distance >= gap / 2, the second's at <= -gap / 2, at t = 0 and
/// t = 1, hence at all t (signed distances are linear in t). The primitives stay at least gap
/// apart. Points within `extent` of the origin (before the push off the plane).
inline CcdQuery separated(CcdKind kind, Rng& r, double gap, double extent) {
  const Vec3 n = r.unit();
  const double o[2] = {r.uniform(-0.5, 0.5) * extent, r.uniform(-0.5, 0.5) * extent};
  const int split = kind == CcdKind::VertexFace ? 1 : 2;
  CcdQuery q;
  q.kind = kind;
  for (int time = 0; time < 2; ++time) {
    auto& x = time == 0 ? q.x0 : q.x1;
    for (int i = 0; i < 4; ++i) {
      Vec3 p = r.point(extent);
      const double side = i < split ? 1.0 : -1.0;
      const double want = side * (0.5 * gap + r.uniform(0.0, 1.0) * r.uniform(0.0, 1.0) * extent);
      p += (want - (n.dot(p) - o[time])) * n;
      x[i] = p;
    }
  }
  return q;
}

}  // namespace tecido::ccd_test
