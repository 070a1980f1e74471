#pragma once
/// Bullet 3.24's vertex-face continuous collision test (engine name `bullet`) as a CcdQuery
/// engine. Only core types cross this header; Bullet stays inside bullet_ccd.cpp.
#include "core/geometry/ccd/query.h"

#include <optional>

namespace tecido::reference {

/// Bullet's answer to a vertex-face query; std::nullopt for edge-edge (Bullet 3.24 has no
/// edge-edge continuous test) and for non-finite input.
///
/// Method: bernsteinCCD(face, node, dt = 1, mrg = SAFE_EPSILON, bary) from
/// BulletSoftBody/btSoftBodyInternals.h, the test Bullet's deformable world runs for
/// self-collision, on Face/Node structs filled as that world fills them (m_x the start, m_v =
/// x1 - x0 so the end is m_x + dt m_v, m_q = m_x + dt m_v, the face's m_n0, m_n1, m_vn). It is a
/// Bernstein-coefficient cull of the coplanarity cubic (margin mrg), a 13-direction k-DOP
/// separating-plane cull, then the cubic's roots in (0, dt] in floating point, each accepted
/// when the vertex is within 1e-6 (absolute, hard-coded) of the triangle's plane and its
/// barycentric coordinates are within a 1e-6-derived tolerance of [0, 1].
///
/// Bullet returns a boolean and barycentric coordinates, not a time. `toi` here is the smallest
/// window end tau (bisection on tau to adjacent doubles, 64 calls at most) for which Bullet
/// reports a hit on the motion restricted to [0, tau] (the same m_x and m_v, dt = tau): its
/// cubic's roots do not depend on dt, only its cut-off root > dt + SIMD_EPSILON does, so tau is
/// the root Bullet accepted, unless its culls change their verdict on the shorter window.
///
/// Known behaviour (documented in bullet_ccd.cpp, recorded by tests/reference/test_bullet_ccd.cpp):
/// a contact at exactly t = 0 is never reported (roots <= 0 are skipped); coplanar-throughout
/// motion is tested only at t = 1; the separating-plane cull declares a miss whenever the
/// vertex's displacement is zero along one of the 13 directions while no triangle corner is
/// within 2.2e-16 of the vertex's start along it (so a vertex at rest is never hit); triangles
/// of squared double area below 2.2e-16 are never hit; its closed-form cubic solver returns a
/// wrong root for strictly monotone cubics, missing such contacts (about one in six on random
/// queries); thresholds are absolute, so the answer depends on the scene's scale.
std::optional<CcdAnswer> bullet_ccd(const CcdQuery& q);

}  // namespace tecido::reference
