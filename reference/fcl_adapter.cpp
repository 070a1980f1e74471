// The only translation unit that includes FCL (FCL itself pulls in libccd's headers).
//
// Segment versus bounded plane: which FCL query, and why. Measured with FCL 0.7.0 (Debian 12)
// against the exact referee (throwaway harness; figures below); tests/reference/test_fcl_adapter.cpp
// re-checks the chosen set-up, including the tilted plane the naive set-up missed.
//  * Chosen: fcl::continuousCollide with CCDC_CONSERVATIVE_ADVANCEMENT + GST_INDEP, a Sphere(0)
//    translated from q1 to q2 against a Box(2 hx, 2 hy, 2 h) at the origin, where q = R^T (p -
//    position) is the segment in the rectangle's frame, axes reflected so that q2 - q1 >= 0
//    componentwise, and h = 2^-42 max|q| a slab half-thickness. FCL dispatches a sphere-box pair to
//    analytic distance and intersection (detail::sphereBoxDistance and sphereBoxIntersect), so the
//    contact test is the box's closed |x| <= hx, |y| <= hy, |z| <= h; an advancement step is
//    distance / (v . n), exact for a head-on approach, converging from below towards an edge. On
//    20000 random segments against random planes this agreed with the exact referee on every
//    hit/miss, t within 1e-9 except 6 oblique approaches to an edge (|dt| <= 9.1e-5).
//  * Why the frame, reflection and slab (each is a workaround for FCL behaviour, measured): posing
//    a zero-thickness Box at the plane and moving the sphere in world coordinates, the naive
//    set-up, missed 658 of those 20000 segments (3.3%), all true hits. (a) When the advancement
//    lands within rounding of the face, the closest points nearly coincide and their difference,
//    the direction n, is rounding noise; v . n < 0 then makes the step 1 and the contact is
//    skipped. In the box's own frame n is an exact axis. (b) A landing that rounds past a
//    zero-thickness face is outside on the far side, moving away: skipped; the slab catches it. (c)
//    A landing inside the box has distance -1 and n = 0, so the bound v . n is +0 or -0; with -0
//    (every component of v negative) the step is -1 / -0 = +inf and the contact is skipped. The
//    reflection makes it +0 (step -inf: contact).
//  * FCL's answers that still differ from the exact ones, by design of the method: (1) the loop
//    returns "collision" only for toc < 1, so a segment ending on the rectangle is a miss; the
//    adapter then asks FCL's discrete collide at q2 (t = 1). (2) The loop stops once its next step
//    would be <= t_err = 1e-4 (hard-coded in ShapeConservativeAdvancementTraversalNode; the
//    request's toc_err and num_max_iterations are ignored by this solver), so a segment that creeps
//    towards the border from outside and passes it within ~1e-4 of its length is reported as a hit
//    (of 20000 random segments crossing the plane within 1e-9 (relative) of the border, about 10000
//    outside it, 5031 were hits); a head-on near miss is answered right. An oblique approach to an
//    edge stops up to ~1e-4 early. (3) Segments within h of the plane count as touching it, and t
//    is the time of reaching the slab (early by h / |v_z|, about 2^-42 for a head-on segment). (4)
//    The frame change rounds: points within a few ulps of the border can land on either side.
//  * Rejected: the default CCDC_NAIVE samples 10 poses at t = i/9 and tunnels through a
//    zero-thickness box (a crossing at t = 0.2 was a miss); CCDC_RAY_SHOOTING is an empty stub in
//    0.7; GST_LIBCCD gave identical answers on the same 20000 + 20000 segments (both solvers use
//    the analytic sphere-box functions) and is not used only because docs/dependencies.md saw it
//    segfault under conservative advancement with other shapes; a Capsule(0, L) against the box
//    with discrete collide gives no time of contact (its contact point is a GJK/EPA witness) and
//    its booleans were wrong in trials: it missed segments lying in the plane (GST_LIBCCD),
//    reported hits for segments crossing the plane 1e-9 and 1e-6 outside the border (GST_INDEP) and
//    missed a crossing at a 1e-6 scale (GST_INDEP); a degenerate triangle (p1, p2, p2) against a
//    two-triangle BVHModel gives only a boolean and inherits fcl_tri_tri's missing in-plane axis
//    for segments (false hits for segments in the plane passing a corner).
//
// Continuous vertex-face and edge-edge (fcl_ccd): FCL's Intersect<double>::intersect_VF and
// intersect_EE (intersect-inl.h), called as they are, with useNewton = true. What they do, read
// from FCL 0.7.0:
//  * velocities v = x1 - x0; cubic coefficients a t^3 + b t^2 + c t + d of the triple product
//    (computeCubicCoeff_VF/EE); if |a|, |b|, |c|, |d| are all below getNearZeroThreshold() =
//    1e-7 the call returns false at once: coplanar-throughout motion (the 2-D problem) is never
//    a contact, nor is any query whose coordinates are small enough (coefficients scale with
//    length^3, so below a length scale of about 5e-3 everything is a miss), nor a
//    near-degenerate one;
//  * solveCubicWithIntervalNewton on [0, 1]: bounds the cubic on the interval from the
//    coefficients' signs, discards intervals whose bounds do not straddle 0, narrows by a Newton
//    step when the derivative's bounds exclude 0, bisects left half first, and once the interval
//    is narrower than getCcdResolution() = 1e-7 accepts it if checkRootValidity holds at its
//    right end r; collision_time = (l + r) / 2. So toi is the midpoint of the first accepted
//    1e-7 interval; a root exactly at t = 1 can be missed (its interval's right end is 1 only if
//    the bisection lands there) and a root at t = 0 is found by its right end ~1e-7;
//  * vertex-face validity (insideTriangle): with n = (b-a) x (c-a), each of the three triple
//    products ((b-p) x (c-p)).n etc. must be >= -getEpsilon() = -1e-5 (absolute, unnormalised:
//    at unit scale a vertex up to ~1e-5 outside an edge counts as inside; a degenerate triangle,
//    n = 0, accepts every vertex in its plane);
//  * edge-edge validity (linelineIntersect): false when either edge's vector has every component
//    below 1e-5 in magnitude (short or zero-length edges never collide) or when the squared
//    sine-like denominator |d12|^2 |d34|^2 - (d12.d34)^2 < 1e-5 (parallel and collinear edges
//    never collide); otherwise the closest points' parameters must lie in [0, 1]; their
//    distance is not checked (the cubic's root makes the lines nearly coplanar).
// Nothing here is repaired; tests/reference/test_fcl_ccd.cpp records FCL's answers on
// degenerate cases and asserts only agreement on ordinary, clearly separated or clearly hitting
// queries.
#include "reference/fcl_adapter.h"

#include <fcl/geometry/bvh/BVH_model.h>
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/sphere.h>
#include <fcl/math/bv/OBBRSS.h>
#include <fcl/narrowphase/collision.h>
#include <fcl/narrowphase/continuous_collision.h>
#include <fcl/narrowphase/detail/traversal/collision/intersect.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace tecido::reference {

bool fcl_tri_tri(const Triangle& a, const Triangle& b) {
  return fcl::detail::Intersect<double>::intersect_Triangle(a[0], a[1], a[2], b[0], b[1], b[2]);
}

std::vector<std::pair<int, int>> fcl_self_collision(const std::vector<Vec3>& vertices,
                                                    const std::vector<std::array<int, 3>>& faces) {
  for (const Vec3& v : vertices)
    if (!v.allFinite()) throw std::invalid_argument("fcl_self_collision: non-finite vertex");
  for (const auto& f : faces)
    for (int i : f)
      if (i < 0 || static_cast<std::size_t>(i) >= vertices.size())
        throw std::invalid_argument("fcl_self_collision: face index " + std::to_string(i) + " out of range");
  std::vector<std::pair<int, int>> pairs;
  if (faces.size() < 2) return pairs;

  std::vector<fcl::Vector3d> verts(vertices.begin(), vertices.end());
  std::vector<fcl::Triangle> tris;
  tris.reserve(faces.size());
  for (const auto& f : faces) tris.emplace_back(f[0], f[1], f[2]);

  fcl::BVHModel<fcl::OBBRSSd> model;
  model.beginModel(static_cast<int>(tris.size()), static_cast<int>(verts.size()));
  model.addSubModel(verts, tris);
  model.endModel();

  // enable_contact off: one contact per intersecting (ordered) primitive pair; a request that
  // cannot fill up never stops the traversal early.
  fcl::CollisionRequestd request(std::numeric_limits<std::size_t>::max(), false);
  fcl::CollisionResultd result;
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  fcl::collide(&model, identity, &model, identity, request, result);

  std::vector<fcl::Contactd> contacts;
  result.getContacts(contacts);
  pairs.reserve(contacts.size());
  for (const auto& c : contacts) {
    int i = c.b1, j = c.b2;
    if (i == j) continue;
    if (i > j) std::swap(i, j);
    const auto& fi = faces[static_cast<std::size_t>(i)];
    const auto& fj = faces[static_cast<std::size_t>(j)];
    bool shares = false;
    for (int u : fi)
      for (int w : fj) shares = shares || u == w;
    if (!shares) pairs.emplace_back(i, j);
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  return pairs;
}

std::optional<SegmentPlaneHit> fcl_segment_plane(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2) {
  const double hx = plane.half_extents.x(), hy = plane.half_extents.y();
  if (!plane.position.allFinite() || !plane.normal.allFinite() || !plane.forward.allFinite() ||
      !p1.allFinite() || !p2.allFinite() || !std::isfinite(hx) || !std::isfinite(hy) || hx < 0 || hy < 0)
    return std::nullopt;

  // The segment in the rectangle's frame (x along forward, y along right, z along normal): the
  // same R^T (p - position) FCL would compute from a posed box, done once here so that FCL sees
  // an axis-aligned box at the origin and computes exact axis directions near its faces.
  Eigen::Matrix3d axes;
  axes.col(0) = plane.forward;
  axes.col(1) = plane.right();
  axes.col(2) = plane.normal;
  Vec3 q1 = axes.transpose() * (p1 - plane.position);
  Vec3 q2 = axes.transpose() * (p2 - plane.position);
  // Reflect axes so the motion is non-negative componentwise (the box is symmetric, so neither
  // the answer nor t changes): FCL's step is distance / (v . n) with n = 0 once the point lands
  // inside the box, and v . 0 = -0 when every component of v is negative, making the step +inf
  // and skipping the contact.
  for (int k = 0; k < 3; ++k)
    if (q2[k] < q1[k]) {
      q1[k] = -q1[k];
      q2[k] = -q2[k];
    }
  if (!q1.allFinite() || !q2.allFinite()) return std::nullopt;
  // Slab half-thickness: a landing that rounds past a zero-thickness face is outside on the far
  // side and is never reported; a slab ~2^10 ulps thick catches it.
  const double half_thickness = std::ldexp(std::max(q1.cwiseAbs().maxCoeff(), q2.cwiseAbs().maxCoeff()), -42);

  const fcl::Boxd box(2 * hx, 2 * hy, 2 * half_thickness);
  const fcl::Sphered point(0);
  const fcl::Transform3d identity = fcl::Transform3d::Identity();
  fcl::Transform3d from = identity, to = identity;
  from.translation() = q1;
  to.translation() = q2;

  const fcl::ContinuousCollisionRequestd request(/*num_max_iterations (ignored by CA)=*/10,
                                                 /*toc_err (ignored by CA)=*/1e-4, fcl::CCDM_TRANS,
                                                 fcl::GST_INDEP, fcl::CCDC_CONSERVATIVE_ADVANCEMENT);
  fcl::ContinuousCollisionResultd result;
  const double ret = fcl::continuousCollide(&point, from, to, &box, identity, identity, request, result);
  if (ret < 0 || !std::isfinite(result.time_of_contact)) return std::nullopt;  // unsupported pair
  if (result.is_collide) return SegmentPlaneHit{true, std::clamp(result.time_of_contact, 0.0, 1.0)};

  // Conservative advancement never reports toc == 1: ask the discrete query at the end pose.
  fcl::CollisionRequestd end_request;
  end_request.gjk_solver_type = fcl::GST_INDEP;
  fcl::CollisionResultd end_result;
  fcl::collide(&point, to, &box, identity, end_request, end_result);
  if (end_result.isCollision()) return SegmentPlaneHit{true, 1.0};
  return SegmentPlaneHit{false, 0.0};
}

CcdAnswer fcl_ccd(const CcdQuery& q) {
  const auto& x0 = q.x0;
  const auto& x1 = q.x1;
  for (std::size_t i = 0; i < 4; ++i)
    if (!x0[i].allFinite() || !x1[i].allFinite()) throw std::domain_error("fcl_ccd: non-finite coordinate");
  double t = 2.0;
  fcl::Vector3d p_i = fcl::Vector3d::Zero();
  bool hit = false;
  if (q.kind == CcdKind::VertexFace)
    hit = fcl::detail::Intersect<double>::intersect_VF(x0[1], x0[2], x0[3], x0[0], x1[1], x1[2], x1[3], x1[0], &t,
                                                       &p_i, /*useNewton=*/true);
  else
    hit = fcl::detail::Intersect<double>::intersect_EE(x0[0], x0[1], x0[2], x0[3], x1[0], x1[1], x1[2], x1[3], &t,
                                                       &p_i, /*useNewton=*/true);
  if (!hit) return CcdAnswer{false, 0.0};
  return CcdAnswer{true, t};
}

}  // namespace tecido::reference
