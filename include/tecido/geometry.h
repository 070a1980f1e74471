#pragma once
/// The geometric types of tecido's public API (tecido/core.h, tecido/referee.h, tecido/harness.h).
///
/// Units: SI (metres, seconds); double precision; right-handed coordinates. Every coordinate
/// must be finite (a NaN or an infinity is a precondition violation: the functions say what they
/// do with one). "Exact" in this API means: the doubles given are taken as the exact rational
/// numbers they represent, and the answer is what exact arithmetic on those numbers gives, with
/// no tolerance and no rounding in the decision.
#include <Eigen/Core>

#include <array>
#include <vector>

namespace tecido {

/// A point or a vector [m].
using Vec3 = Eigen::Vector3d;

/// A closed triangle: three corners, in order. Degenerate triangles (repeated or collinear
/// corners) are the segment or point they span.
using Triangle = std::array<Vec3, 3>;

/// A closed rectangle in space: its centre, unit normal, unit forward (orthogonal to the normal)
/// and half extents along forward and along right = normal x forward [m]. Closed: the border
/// counts. Two-sided.
struct Rectangle {
  Vec3 position = Vec3::Zero();
  Vec3 normal = Vec3::UnitZ();
  Vec3 forward = Vec3::UnitX();
  double half_forward = 1.0;  ///< >= 0
  double half_right = 1.0;    ///< >= 0
};

/// A segment against a rectangle: whether it meets it, and where.
struct PlaneHit {
  bool hit = false;
  /// Fraction along from -> to of the first point of the segment on the rectangle, in [0, 1];
  /// 0 when !hit.
  double t = 0.0;
};

/// The two kinds of continuous-collision query.
enum class MotionKind {
  VertexFace,  ///< x[0] the vertex, x[1], x[2], x[3] the triangle's corners
  EdgeEdge     ///< x[0]-x[1] the first edge, x[2]-x[3] the second
};

/// Four points moving linearly over one step: p_i(t) = (1 - t) x0[i] + t x1[i], t in [0, 1]
/// (t is the fraction of the step, not seconds). The primitives are closed: touching counts.
struct Motion {
  MotionKind kind = MotionKind::VertexFace;
  std::array<Vec3, 4> x0;  ///< positions at t = 0 [m]
  std::array<Vec3, 4> x1;  ///< positions at t = 1 [m]
};

/// A continuous-collision answer: whether the primitives touch at some t in [0, 1], and the
/// earliest such t (0 when !hit).
struct Contact {
  bool hit = false;
  double toi = 0.0;
};

/// A triangle mesh's faces: three 0-based vertex indices each, distinct, in [0, vertex count).
using Faces = std::vector<std::array<int, 3>>;

/// Two faces (i < j) of a mesh that intersect (self_collisions).
using FacePair = std::array<int, 2>;

/// A mesh edge (a, b), a < b, as vertex indices.
using Edge = std::array<int, 2>;

/// The contacts of one mesh moving linearly over a step (continuous_self_collisions): vertex-face
/// pairs (vertex, face), the vertex not a corner of the face, and edge-edge pairs ((a, b), (c, d)),
/// a < b, c < d, (a, b) < (c, d), the edges sharing no vertex; each list sorted lexicographically.
/// The same lists as `tecido selfcollide --to --json` prints.
struct SelfContacts {
  std::vector<std::array<int, 2>> vertex_face;
  std::vector<std::array<Edge, 2>> edge_edge;
};

}  // namespace tecido
