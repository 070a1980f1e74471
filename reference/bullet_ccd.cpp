// Bullet's vertex-face continuous collision test; built in the tecido_bullet library with the
// float64 Bullet (BT_USE_DOUBLE_PRECISION private). bernsteinCCD is static inline in
// btSoftBodyInternals.h, so it is called directly on Face/Node structs built here, with no world.
//
// What bernsteinCCD(face, node, dt, mrg, bary) does (Bullet 3.24, read from the header):
//  1. bernsteinVFTest: Bernstein coefficients k0..k3 (times 3) of the coplanarity cubic from
//     node m_x, m_q and the face's m_n0, m_n1, m_vn; a miss when all four are > mrg or all are
//     < -mrg. (The rest of that function is unreachable: it returns true after the cull.)
//  2. continuousCollisionDetection(face, node, dt, 1e-6, bary): mrg is NOT passed on;
//     a. hasSeparatingPlane: for each of 13 k-DOP directions d, s = sign(d . dt v_node) with a
//        dead zone of SIMD_EPSILON; a miss when no triangle corner (start or end, relative to
//        the node's start) has that same sign. When s = 0 (the vertex does not move along d)
//        any corner off the dead zone counts as separated, whatever side it is on: a vertex
//        at rest, or moving parallel to a coordinate plane or a 45-degree plane, is reported
//        separated from triangles that sweep right through it.
//     b. the cubic's coefficients in floating point (independent of dt); all four below
//        SAFE_EPSILON (absolute): roots {0, dt}; then a quadratic or linear fallback by the same
//        absolute threshold, else SolveP3 (Bullet's poly34, closed form). Roots sorted. SolveP3 has a
//        defect: when q = (a^2 - 3b)/9 < 0 (the cubic is strictly monotone, one real root) it
//        sets q = SIMD_EPSILON and returns a wrong root, so such contacts are missed (measured: 84
//        of 434 contacts among 20000 random unit-scale queries; none invented);
//     c. roots <= 0 are skipped (no contact at t = 0); a root > dt + SIMD_EPSILON ends the
//        search; at each root the positions m_x + root m_v are tested by proximityTest with
//        margin 1e-6: |(x4 - x3) . n_unit| <= 1e-6 and barycentric weights within
//        [-delta, 1 + delta], delta = 1e-6 / sqrt(|x13 x x23| / 2); a triangle with
//        |x13|^2 |x23|^2 - (x13 . x23)^2 < SIMD_EPSILON (absolute) is never hit.
// The face fields are filled as btDeformableMultiBodyDynamicsWorld::performGeometricCollisions
// fills them before it runs this test: m_n0 = (x2 - x1) x (x3 - x1) at the start, m_q = m_x +
// dt m_v, m_n1 the same cross product at m_q, m_vn = (v2 - v1) x (v3 - v1) dt^2.
//
// The margin: mrg only feeds the cull of step 1 (a larger one culls less and costs time, it
// cannot add a contact). Measured on 20000 contacts exactly at t = 1 on a unit-scale tilted plane
// (dyadic end points, generic start points, so m_q = m_x + m_v rounds away from x1 and k3 = 0
// becomes a tiny +-value): mrg <= 1e-16 culled 79 of the 11617 contacts that step 2 accepts,
// mrg >= 1e-15 culled none. This adapter passes SAFE_EPSILON = 100 DBL_EPSILON ~ 2.2e-14, the
// value Bullet's own deformable world passes (CollideCCD), within a decade of the smallest that
// works at unit scale. It is absolute, like the 1e-6 of step 2c: at other scales it is too small
// or too large.
#include "reference/bullet_ccd.h"

#include <BulletSoftBody/btSoftBody.h>
#include <BulletSoftBody/btSoftBodyInternals.h>

#include <cmath>
#include <cstdint>
#include <cstring>

static_assert(sizeof(btScalar) == sizeof(double), "the Bullet adapters need the float64 Bullet build");

namespace tecido::reference {
namespace {

btVector3 bt(const Vec3& v) { return btVector3(v.x(), v.y(), v.z()); }

/// Whether Bullet reports a contact for the motion restricted to [0, dt]: node i starts at
/// x0[i] with velocity x1[i] - x0[i].
bool bullet_hit_within(const CcdQuery& q, double dt) {
  btSoftBody::Node nodes[4];
  for (int i = 0; i < 4; ++i) {
    btSoftBody::Node& n = nodes[i];
    ZeroInitialize(n);
    n.m_x = bt(q.x0[static_cast<std::size_t>(i)]);
    n.m_v = bt(q.x1[static_cast<std::size_t>(i)]) - n.m_x;
    n.m_q = n.m_x + dt * n.m_v;
  }
  btSoftBody::Face face;
  ZeroInitialize(face);
  for (int i = 0; i < 3; ++i) face.m_n[i] = &nodes[i + 1];
  const btSoftBody::Node *a = face.m_n[0], *b = face.m_n[1], *c = face.m_n[2];
  face.m_n0 = (b->m_x - a->m_x).cross(c->m_x - a->m_x);
  face.m_n1 = (b->m_q - a->m_q).cross(c->m_q - a->m_q);
  face.m_vn = (b->m_v - a->m_v).cross(c->m_v - a->m_v) * dt * dt;
  btVector3 bary;
  return bernsteinCCD(&face, &nodes[0], dt, SAFE_EPSILON, bary);
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

}  // namespace

std::optional<CcdAnswer> bullet_ccd(const CcdQuery& q) {
  if (q.kind != CcdKind::VertexFace) return std::nullopt;
  for (int i = 0; i < 4; ++i)
    if (!q.x0[static_cast<std::size_t>(i)].allFinite() || !q.x1[static_cast<std::size_t>(i)].allFinite())
      return std::nullopt;
  if (!bullet_hit_within(q, 1.0)) return CcdAnswer{false, 0.0};
  // The smallest window [0, tau] with a hit: bisection on the bit patterns of tau in (0, 1]
  // (they order non-negative doubles); tau = 0 itself can never hit (roots <= 0 are skipped).
  std::uint64_t lo = bits(0.0), hi = bits(1.0);
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    (bullet_hit_within(q, from_bits(mid)) ? hi : lo) = mid;
  }
  return CcdAnswer{true, from_bits(hi)};
}

}  // namespace tecido::reference
