#pragma once
/// FCL 0.7 (Pan, Chitta, Manocha 2012) as a triangle-triangle, self-collision and
/// segment-versus-bounded-plane engine. Only core types cross this header; FCL stays inside
/// fcl_adapter.cpp.
#include "core/geometry/bounded_plane.h"
#include "core/geometry/ccd/query.h"
#include "core/geometry/segment_plane.h"
#include "core/geometry/types.h"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace tecido::reference {

/// Whether the closed triangles intersect according to
/// fcl::detail::Intersect<double>::intersect_Triangle: a separating-axis test over 17 axes
/// (both normals, 9 edge-edge crosses, 6 in-plane edge normals) in floating point without
/// tolerance; touching (shared vertex or edge, vertex on face, coplanar overlap) counts.
/// Not the ODE-style variant, which misses many true intersections. Known limit: for a
/// degenerate (collinear) triangle the axis set lacks the segment's in-plane normal, so a
/// segment coplanar with the other triangle and passing just outside one of its corners is
/// reported as intersecting.
bool fcl_tri_tri(const Triangle& a, const Triangle& b);

/// The intersecting pairs of triangles of the mesh that share no vertex index, each as (i, j)
/// with i < j in `faces` order, sorted, without duplicates. Method: the mesh as one
/// fcl::BVHModel<OBBRSS<double>> collided against itself (fcl::collide, identity poses,
/// CollisionRequest with num_max_contacts = every ordered pair of faces and enable_contact off:
/// without contact points each intersecting triangle pair is reported once per order, and the
/// traversal cannot stop early), leaf test intersect_Triangle as in fcl_tri_tri. FCL has no
/// adjacency filter; pairs (i, i) and pairs sharing a vertex index are removed here.
/// Throws std::invalid_argument on a face index outside `vertices` or a non-finite vertex.
std::vector<std::pair<int, int>> fcl_self_collision(const std::vector<Vec3>& vertices,
                                                    const std::vector<std::array<int, 3>>& faces);

/// Segment p1 -> p2 against the closed rectangle of `plane`, answered by FCL: hit and the
/// fraction along the segment of the first contact. Method: continuous collision
/// (fcl::continuousCollide, CCDC_CONSERVATIVE_ADVANCEMENT with GST_INDEP's analytic sphere-box
/// distance; conservative advancement, Mirtich 1996) of a Sphere of radius 0 translated along
/// the segment, expressed in the rectangle's frame, against a Box(2 hx, 2 hy, 2 h) at the origin,
/// h = 2^-42 times the largest segment coordinate in that frame. When FCL finds no contact
/// before t = 1 the adapter asks FCL's discrete collide at p2 (contact there: t = 1).
/// Known differences from the exact answer (fcl_adapter.cpp has the measurements and the reasons
/// for the frame, the slab and an axis reflection): segments passing the rectangle's border
/// within about 1e-4 of their length count as hits (FCL's hard-coded t_err); an oblique approach
/// to an edge reports t up to ~1e-4 early; segments within h of the plane touch it.
/// Returns std::nullopt when FCL cannot answer: a non-finite input, a negative half extent, or
/// FCL reporting an unsupported query.
std::optional<SegmentPlaneHit> fcl_segment_plane(const BoundedPlane& plane, const Vec3& p1, const Vec3& p2);

/// FCL's continuous vertex-face or edge-edge test (engine name `fcl`):
/// fcl::detail::Intersect<double>::intersect_VF(a0, b0, c0, p0, a1, b1, c1, p1, &t, &p_i, true)
/// (triangle corners first, then the vertex, at t = 0 and then t = 1) and
/// intersect_EE(a0, b0, c0, d0, a1, b1, c1, d1, &t, &p_i, true) (edges a-b and c-d), from
/// fcl/narrowphase/detail/traversal/collision/intersect.h: the coplanarity cubic of Provot 1997
/// (Tang et al. 2009, eq. 1) in floating point, roots searched by interval Newton bisection
/// over [0, 1], left half first (useNewton = true, FCL's default; with false FCL takes the
/// first valid root of its closed-form cubic solver in the solver's order, not the earliest),
/// down to intervals narrower than 1e-7, the first accepted one giving toi, its midpoint. A root
/// is accepted when, at the interval's right end, the vertex passes an in-triangle test with
/// absolute tolerance 1e-5 on unnormalised triple products, or the two lines' closest points
/// lie within both segments (no distance check; lines whose direction vectors are shorter than
/// 1e-5 per component or nearly parallel, |cross|^2 < 1e-5, are rejected).
/// Known behaviour (not repaired; fcl_adapter.cpp): when all four cubic coefficients are below
/// 1e-7 in magnitude (coplanar-throughout motion, or any query at a scale below ~5e-3) FCL
/// reports no contact; tolerances are absolute, so answers depend on the scene's scale; toi is
/// accurate to about 1e-7. Returns hit = false with toi = 0 for a miss. Throws
/// std::domain_error if a coordinate is NaN or infinite.
CcdAnswer fcl_ccd(const CcdQuery& q);

}  // namespace tecido::reference
