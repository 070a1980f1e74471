#pragma once
/// FCL 0.7 (Pan, Chitta, Manocha 2012) as a triangle-triangle, self-collision and
/// segment-versus-bounded-plane engine. Only core types cross this header; FCL stays inside
/// fcl_adapter.cpp.
#include "core/geometry/bounded_plane.h"
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

}  // namespace tecido::reference
