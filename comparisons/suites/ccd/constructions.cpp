#include "comparisons/suites/ccd/constructions.h"

#include <cmath>
#include <utility>

namespace tecido::suites::ccd {

void random_motion(CcdKind kind, Rng& r, double small_motion, std::size_t count, std::vector<KnownQuery>& out) {
  for (std::size_t k = 0; k < count; ++k) {
    KnownQuery kq;
    kq.q.kind = kind;
    for (int i = 0; i < 4; ++i) {
      kq.q.x0[i] = r.in_box(0.0, 1.0);
      kq.q.x1[i] = k % 2 ? kq.q.x0[i] + r.in_box(-small_motion, small_motion) : r.in_box(0.0, 1.0);
    }
    out.push_back(kq);
  }
}

double dyadic(Rng& r, int lo, int hi, int den) {
  return static_cast<double>(lo + static_cast<int>(r.below(static_cast<std::uint64_t>(hi - lo + 1)))) / den;
}

Vec3 dyadic_vec(Rng& r, int m, int den) {
  const double x = dyadic(r, -m, m, den), y = dyadic(r, -m, m, den), z = dyadic(r, -m, m, den);
  return Vec3(x, y, z);
}

CcdQuery moving_through(CcdKind kind, double t, const std::array<Vec3, 4>& at, const std::array<Vec3, 4>& v) {
  CcdQuery q;
  q.kind = kind;
  for (std::size_t i = 0; i < 4; ++i) {
    q.x0[i] = at[i] - t * v[i];
    q.x1[i] = at[i] + (1.0 - t) * v[i];
  }
  return q;
}

KnownQuery known_hit(const CcdQuery& q, double t) { return KnownQuery{q, 1, t}; }
KnownQuery known_miss(const CcdQuery& q) { return KnownQuery{q, 0, 0.0}; }

Affine random_affine(Rng& r) {
  for (;;) {
    Affine a;
    for (Vec3& row : a.rows) row = dyadic_vec(r, 8, 8);
    a.o = dyadic_vec(r, 64, 64);
    // The determinant of small dyadics is exact.
    const double det = a.rows[0].dot(a.rows[1].cross(a.rows[2]));
    if (std::fabs(det) >= 0.125) return a;
  }
}

CcdQuery mapped(const CcdQuery& q, const Affine& a) {
  CcdQuery out = q;
  for (auto* frame : {&out.x0, &out.x1})
    for (Vec3& p : *frame) p = Vec3(a.rows[0].dot(p), a.rows[1].dot(p), a.rows[2].dot(p)) + a.o;
  return out;
}

PlaneFrame random_plane(Rng& r) {
  for (;;) {
    PlaneFrame f{dyadic_vec(r, 64, 64), dyadic_vec(r, 8, 8), dyadic_vec(r, 8, 8)};
    if (f.e1.cross(f.e2).squaredNorm() >= 0.0625) return f;
  }
}

CcdQuery permuted_axes(const CcdQuery& q, Rng& r) {
  std::array<int, 3> axis = {0, 1, 2};
  for (int i = 2; i > 0; --i) std::swap(axis[i], axis[r.below(static_cast<std::uint64_t>(i + 1))]);
  const Vec3 sign(r.below(2) ? -1.0 : 1.0, r.below(2) ? -1.0 : 1.0, r.below(2) ? -1.0 : 1.0);
  CcdQuery out = q;
  for (auto* frame : {&out.x0, &out.x1})
    for (Vec3& p : *frame) p = Vec3(sign[0] * p[axis[0]], sign[1] * p[axis[1]], sign[2] * p[axis[2]]);
  return out;
}

CcdQuery relabelled(const CcdQuery& q, Rng& r) {
  CcdQuery out = q;
  auto swap_points = [&out](int i, int j) {
    std::swap(out.x0[i], out.x0[j]);
    std::swap(out.x1[i], out.x1[j]);
  };
  if (q.kind == CcdKind::VertexFace) {
    for (int i = 3; i > 1; --i) swap_points(i, 1 + static_cast<int>(r.below(static_cast<std::uint64_t>(i))));
  } else {
    if (r.below(2)) swap_points(0, 1);
    if (r.below(2)) swap_points(2, 3);
    if (r.below(2)) swap_points(0, 2), swap_points(1, 3);
  }
  return out;
}

CcdQuery scaled(const CcdQuery& q, int e) {
  CcdQuery out = q;
  for (auto* frame : {&out.x0, &out.x1})
    for (Vec3& p : *frame)
      for (int a = 0; a < 3; ++a) p[a] = std::ldexp(p[a], e);
  return out;
}

CcdQuery translated(const CcdQuery& q, const Vec3& d) {
  CcdQuery out = q;
  for (auto* frame : {&out.x0, &out.x1})
    for (Vec3& p : *frame) p += d;
  return out;
}

void rescaled_queries(Rng& r, KnownQuery (*generic)(Rng&), const std::vector<int>& scale,
                      const std::vector<int>& offset, std::size_t count, std::vector<KnownQuery>& out) {
  const std::size_t n = scale.size() + offset.size();
  for (std::size_t k = 0; k < count; ++k) {
    KnownQuery kq = generic(r);
    const std::size_t j = k % n;
    if (j < scale.size()) {
      kq.q = scaled(kq.q, scale[j]);
    } else {
      const double d = std::ldexp(1.0, offset[j - scale.size()]);
      kq.q = translated(kq.q, Vec3(r.below(2) ? d : -d, r.below(2) ? d : -d, r.below(2) ? d : -d));
    }
    out.push_back(kq);
  }
}

}  // namespace tecido::suites::ccd
