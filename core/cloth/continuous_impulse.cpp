#include "core/cloth/continuous_impulse.h"

#include "core/geometry/ccd/ccd.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

/// A contact's particles, weights and normal (continuous_impulse.h, step 2).
struct ContactFrame {
  std::array<int, 4> idx;
  std::array<double, 4> w;
  Vec3 n = Vec3::Zero();
};

Vec3 at(const std::vector<Vec3>& x0, const std::vector<Vec3>& x1, int i, double t) { return x0[i] + t * (x1[i] - x0[i]); }

/// Barycentric coordinates (u, v, w) of p's projection onto triangle abc, clamped into the
/// triangle (negative weights set to 0, the rest rescaled); the centroid for a zero-area triangle.
std::array<double, 3> clamped_barycentric(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e0 = b - a, e1 = c - a, d = p - a;
  const double d00 = e0.dot(e0), d01 = e0.dot(e1), d11 = e1.dot(e1), d20 = d.dot(e0), d21 = d.dot(e1);
  const double den = d00 * d11 - d01 * d01;
  if (!(den > 1e-30 * d00 * d11)) return {1.0 / 3, 1.0 / 3, 1.0 / 3};
  std::array<double, 3> bary;
  bary[1] = (d11 * d20 - d01 * d21) / den;
  bary[2] = (d00 * d21 - d01 * d20) / den;
  bary[0] = 1.0 - bary[1] - bary[2];
  double sum = 0.0;
  for (double& x : bary) sum += (x = std::max(x, 0.0));
  for (double& x : bary) x /= sum;
  return bary;
}

/// Parameters (s, r) of the closest points of segments p0p1 and q0q1, clamped to [0, 1]
/// (Ericson, Real-Time Collision Detection, 5.1.9).
std::array<double, 2> closest_parameters(const Vec3& p0, const Vec3& p1, const Vec3& q0, const Vec3& q1) {
  const Vec3 d1 = p1 - p0, d2 = q1 - q0, r = p0 - q0;
  const double a = d1.dot(d1), e = d2.dot(d2), f = d2.dot(r);
  if (a <= 0.0 && e <= 0.0) return {0.0, 0.0};
  if (a <= 0.0) return {0.0, std::clamp(f / e, 0.0, 1.0)};
  const double c = d1.dot(r);
  if (e <= 0.0) return {std::clamp(-c / a, 0.0, 1.0), 0.0};
  const double b = d1.dot(d2), den = a * e - b * b;
  double s = den > 0.0 ? std::clamp((b * f - c * e) / den, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if (t < 0.0) t = 0.0, s = std::clamp(-c / a, 0.0, 1.0);
  else if (t > 1.0) t = 1.0, s = std::clamp((b - c) / a, 0.0, 1.0);
  return {s, t};
}

/// Weighted sum of the contact's points.
Vec3 weighted(const ContactFrame& f, const std::vector<Vec3>& x) {
  Vec3 s = Vec3::Zero();
  for (int k = 0; k < 4; ++k) s += f.w[k] * x[f.idx[k]];
  return s;
}

/// Weights and normal at time t (step 2); n stays zero when nothing gives a direction.
ContactFrame frame_at(const ContactFrame& base, CcdKind kind, const std::vector<Vec3>& x0, const std::vector<Vec3>& x1,
                      double t) {
  ContactFrame f = base;
  std::array<Vec3, 4> p;
  for (int k = 0; k < 4; ++k) p[k] = at(x0, x1, f.idx[k], t);
  Vec3 n;
  if (kind == CcdKind::VertexFace) {
    const auto b = clamped_barycentric(p[0], p[1], p[2], p[3]);
    f.w = {1.0, -b[0], -b[1], -b[2]};
    n = (p[2] - p[1]).cross(p[3] - p[1]);
  } else {
    const auto sr = closest_parameters(p[0], p[1], p[2], p[3]);
    f.w = {1.0 - sr[0], sr[0], -(1.0 - sr[1]), -sr[1]};
    n = (p[1] - p[0]).cross(p[3] - p[2]);
  }
  const double scale = (p[1] - p[0]).squaredNorm() + (p[3] - p[2]).squaredNorm() + (p[2] - p[1]).squaredNorm();
  if (n.squaredNorm() <= 1e-24 * scale * scale) n = weighted(f, x0);       // degenerate: along the starting separation
  if (n.squaredNorm() == 0.0) n = -(weighted(f, x1) - weighted(f, x0));   // ... else against the relative motion
  f.n = n.squaredNorm() > 0.0 ? Vec3(n.normalized()) : Vec3::Zero();
  return f;
}

/// The impulse of one contact (step 3); true when it changed a velocity.
bool resolve(const ContactFrame& f, const std::vector<Vec3>& x0, std::vector<Vec3>& x1, std::vector<Vec3>& v,
             const std::vector<double>& inv_mass, double h) {
  if (f.n == Vec3::Zero()) return false;
  Vec3 n = f.n;
  double d0 = n.dot(weighted(f, x0));
  double vn = n.dot(weighted(f, x1) - weighted(f, x0)) / h;
  if (d0 == 0.0) return false;  // touching at the start: no side to keep
  if (d0 < 0.0) n = -n, d0 = -d0, vn = -vn;
  const double target = -(1.0 - kKeptGap) * d0 / h;
  if (!(vn < target)) return false;
  double den = 0.0;
  for (int k = 0; k < 4; ++k) den += f.w[k] * f.w[k] * inv_mass[f.idx[k]];
  if (!(den > 0.0)) return false;
  const double impulse = (target - vn) / den;
  for (int k = 0; k < 4; ++k) {
    const Vec3 dv = (f.w[k] * inv_mass[f.idx[k]] * impulse) * n;
    v[f.idx[k]] += dv;
    x1[f.idx[k]] += h * dv;
  }
  return true;
}

}  // namespace

int apply_contact_impulses(const ContinuousContacts& c, const std::vector<std::array<int, 3>>& triangles,
                           const std::vector<Vec3>& x0, std::vector<Vec3>& x1, std::vector<Vec3>& v,
                           const std::vector<double>& inv_mass, double h) {
  int applied = 0;
  auto one = [&](CcdKind kind, const std::array<int, 4>& idx) {
    const CcdQuery q = [&] {
      CcdQuery qq;
      qq.kind = kind;
      for (int k = 0; k < 4; ++k) qq.x0[k] = x0[idx[k]], qq.x1[k] = x1[idx[k]];
      return qq;
    }();
    const CcdAnswer a = ccd(q);  // x1 may have changed since detection: ask again
    if (!a.hit) return;
    applied += resolve(frame_at(ContactFrame{idx, {}, Vec3::Zero()}, kind, x0, x1, a.toi), x0, x1, v, inv_mass, h);
  };
  for (const auto& [p, t] : c.vertex_face) {
    const auto& tri = triangles[t];
    one(CcdKind::VertexFace, {p, tri[0], tri[1], tri[2]});
  }
  for (const auto& [e, g] : c.edge_edge) one(CcdKind::EdgeEdge, {e[0], e[1], g[0], g[1]});
  return applied;
}

}  // namespace tecido
