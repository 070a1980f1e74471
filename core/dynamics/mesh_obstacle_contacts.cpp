#include "core/dynamics/mesh_obstacle_contacts.h"

#include "core/geometry/ccd/ccd.h"
#include "core/geometry/orient_predicates.h"

#include <algorithm>
#include <cmath>

namespace tecido {

namespace {

std::int8_t sign_of(double s) { return s > 0.0 ? 1 : (s < 0.0 ? -1 : 0); }

struct Box3 {
  Vec3 lo, hi;
  void grow(const Vec3& p) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  bool overlaps(const Box3& b) const {
    return lo.x() <= b.hi.x() && b.lo.x() <= hi.x() && lo.y() <= b.hi.y() && b.lo.y() <= hi.y() &&
           lo.z() <= b.hi.z() && b.lo.z() <= hi.z();
  }
};

Box3 segment_box(const Vec3& a, const Vec3& b) { return Box3{a.cwiseMin(b), a.cwiseMax(b)}; }

Vec3 unit_normal(const ObstaclePose& pose, const std::array<int, 3>& t) {
  const Vec3 &a = pose.vertices[t[0]], &b = pose.vertices[t[1]], &c = pose.vertices[t[2]];
  const Vec3 n = (b - a).cross(c - a);
  const double len = n.norm();
  return len > 0.0 ? Vec3(n / len) : Vec3::UnitZ();
}

}  // namespace

int triangle_side(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& x) {
  return orient3d_sign(pose.vertices[t[0]], pose.vertices[t[1]], pose.vertices[t[2]], x);
}

std::int8_t initial_triangle_side(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& x, const Vec3& v,
                                  const Vec3& a) {
  std::int8_t s = static_cast<std::int8_t>(triangle_side(pose, t, x));
  // +1 is the side opposite the normal n: a particle moving along +n comes from there.
  const Vec3 n = unit_normal(pose, t);
  if (s == 0) s = sign_of(n.dot(v));
  if (s == 0) s = sign_of(n.dot(a));
  return s == 0 ? 1 : s;
}

Vec3 triangle_normal_towards(const ObstaclePose& pose, const std::array<int, 3>& t, int side) {
  return -static_cast<double>(side) * unit_normal(pose, t);
}

MeshHit mesh_earliest_hit(const Obstacle& o, const ObstaclePose& p0, const ObstaclePose& p1, const Vec3& x0,
                          const Vec3& x1, const std::int8_t* side, const std::uint8_t* rest, bool first_only) {
  MeshHit best;
  const Box3 path = segment_box(x0, x1);
  for (std::size_t f = 0; f < o.triangles.size(); ++f) {
    if (rest[f]) continue;
    const auto& t = o.triangles[f];
    Box3 tri = segment_box(p0.vertices[t[0]], p1.vertices[t[0]]);
    for (int k = 1; k < 3; ++k) {
      tri.grow(p0.vertices[t[k]]);
      tri.grow(p1.vertices[t[k]]);
    }
    if (!tri.overlaps(path)) continue;
    if (triangle_side(p1, t, x1) == side[f]) continue;  // still strictly on its side
    CcdQuery q;
    q.kind = CcdKind::VertexFace;
    q.x0 = {x0, p0.vertices[t[0]], p0.vertices[t[1]], p0.vertices[t[2]]};
    q.x1 = {x1, p1.vertices[t[0]], p1.vertices[t[1]], p1.vertices[t[2]]};
    const CcdAnswer a = ccd(q);
    if (!a.hit || !(a.toi < best.s)) continue;
    best = MeshHit{static_cast<int>(f), std::clamp(a.toi, 0.0, 1.0)};
    if (first_only) break;
  }
  return best;
}

Vec3 place_on_triangle(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& bary, int side) {
  const Vec3 &a = pose.vertices[t[0]], &b = pose.vertices[t[1]], &c = pose.vertices[t[2]];
  Vec3 x = bary[0] * a + bary[1] * b + bary[2] * c;
  const Vec3 n = triangle_normal_towards(pose, t, side);
  double step = 0x1p-52 * std::max({x.cwiseAbs().maxCoeff(), a.cwiseAbs().maxCoeff(), 1e-300});
  for (int tries = 0; tries < 64 && orient3d_sign(a, b, c, x) == -side; ++tries) {
    x += step * n;
    step *= 2.0;
  }
  return x;
}

Vec3 triangle_projection_barycentric(const ObstaclePose& pose, const std::array<int, 3>& t, const Vec3& x) {
  const Vec3 &a = pose.vertices[t[0]], &b = pose.vertices[t[1]], &c = pose.vertices[t[2]];
  const Vec3 n = (b - a).cross(c - a);
  const double n2 = n.squaredNorm();
  if (!(n2 > 0.0)) return Vec3(-1, -1, -1);
  const double wa = (c - b).cross(x - b).dot(n) / n2, wb = (a - c).cross(x - c).dot(n) / n2;
  return Vec3(wa, wb, 1.0 - wa - wb);
}

}  // namespace tecido
