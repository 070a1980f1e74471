#pragma once
/// tecido's own engine (library tecido::core, Eigen only): its geometric tests, the ones the
/// `core` engine of the command line answers with. Thread-safe (no shared state but per-thread
/// statistics); the same input gives the same bits on every machine with IEEE doubles.
/// Types and what "exact" means: tecido/geometry.h.
#include <tecido/geometry.h>

#include <vector>

namespace tecido::core {

/// Whether the closed triangles a and b share at least one point (crossing, touching at a vertex
/// or along an edge, coplanar overlap, a shared vertex or edge all count). Exact: the answer is
/// the exact-arithmetic answer for every finite input, independent of the order of the corners
/// and of a and b (Guigue-Devillers 2003 on Shewchuk's filtered exact predicates).
/// Precondition: finite coordinates (the answer for NaN or infinity is unspecified).
bool tri_tri(const Triangle& a, const Triangle& b);

/// The segment from -> to against the closed rectangle `r`. The hit/miss decision is exact (as
/// tecido::referee::segment_plane decides it, for every finite input); `t` is a floating-point
/// value (a few ulps from the exact fraction). `r.normal` and `r.forward` should be unit and
/// orthogonal; the rectangle is what the formulas of docs/design.md section 1 describe with them
/// as given. Precondition: finite coordinates.
PlaneHit segment_plane(const Rectangle& r, const Vec3& from, const Vec3& to);

/// Continuous collision of `m` with default settings (1e-9 of the query's scale as the distance
/// tolerance). Conservative, not exact: never a false negative (a miss is answered only on a
/// certificate), a hit means the primitives come within that tolerance, and toi <= the true
/// first time of contact (typically within 4e-14 of it on a transversal crossing). NaN or
/// infinite input answers a hit at toi = 0.
Contact ccd(const Motion& m);

/// The pairs (i, j), i < j, of faces of the mesh (V, F) that intersect, closed triangles
/// (touching counts), leaving out pairs that share a vertex index; sorted. Exact (tri_tri on
/// every candidate of a box tree): the answer of `tecido selfcollide --mesh M.obj` (engine core).
/// Throws std::domain_error for a non-finite vertex, std::invalid_argument for a face naming a
/// vertex outside V or repeating one.
std::vector<FacePair> self_collisions(const std::vector<Vec3>& V, const Faces& F);

/// The vertex-face and edge-edge pairs of the mesh F moving linearly from V0 to V1 (same vertex
/// count) that core's continuous test (ccd above) says touch: conservative, never a contact
/// missed; a near miss within ccd's tolerance may be included. The answer of
/// `tecido selfcollide --mesh V0.obj --to V1.obj --engines core-brute` (core's test on every pair;
/// computed here by a box tree, with the same answer). tecido::referee::continuous_self_collisions
/// confirms each pair exactly. Throws as self_collisions does (and std::invalid_argument for
/// frames of different sizes).
SelfContacts continuous_self_collisions(const std::vector<Vec3>& V0, const std::vector<Vec3>& V1, const Faces& F);

}  // namespace tecido::core
