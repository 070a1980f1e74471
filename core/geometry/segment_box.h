#pragma once
/// A particle's path against a solid box, in the box's local frame (axes along its edges, origin
/// at its centre, half extents h): a slab test (Kay and Kajiya 1986) on the open box
/// |q_i| < h_i. For a moving box the start and end points are each taken into the box's frame
/// at their own time, so the relative motion is the straight segment q0 -> q1 (exact for a
/// translating box; for a rotating one the relative path is linearised over the (sub-)step).
/// Faces are numbered 2 i + (0 for -h_i, 1 for +h_i), i = 0, 1, 2 (x, y, z).
#include "core/geometry/types.h"

namespace tecido {

/// True when |q_i| < h_i on every axis: the inside test every box decision in the engine uses
/// (a point on a face, edge or corner is outside).
inline bool inside_box(const Vec3& q, const Vec3& h) {
  return std::abs(q.x()) < h.x() && std::abs(q.y()) < h.y() && std::abs(q.z()) < h.z();
}

struct BoxEntry {
  bool hit = false;
  double s = 0.0;  ///< fraction along q0 -> q1 at which the path reaches the box, in [0, 1]
  int face = 0;    ///< the face it enters through (2 axis + (sign > 0))
};

/// Whether the segment q0 -> q1 enters the open box, where it first reaches the closed box and
/// through which face: per axis the open interval of s where |q_i(s)| < h_i, intersected; a hit
/// when the intersection meets [0, 1]. Moving along a face or leaving from it is no hit. An end
/// point inside (inside_box) is always a hit (face: the one nearest to it), so rounding in the
/// slab fractions can never let a step end inside.
BoxEntry segment_enters_box(const Vec3& q0, const Vec3& q1, const Vec3& h);

/// The face of the box nearest to q (smallest h_i - |q_i|).
int nearest_box_face(const Vec3& q, const Vec3& h);

/// q moved onto `face` (that coordinate set to +-h, the others clamped to [-h, h]).
Vec3 project_on_box_face(const Vec3& q, const Vec3& h, int face);

/// Outward unit normal of `face` in the box's frame.
inline Vec3 box_face_normal(int face) {
  Vec3 n = Vec3::Zero();
  n[face / 2] = (face & 1) ? 1.0 : -1.0;
  return n;
}

/// The largest depth min_i (h_i - |q_i(s)|) over s in [0, 1] of the segment q0 -> q1 inside the
/// box (how far its deepest point is from the nearest face), or 0 when the segment does not
/// enter the open box. The depth is concave and piecewise linear in s, so its maximum is at an
/// end or where two of its six linear pieces cross: those 17 candidates are evaluated.
double segment_box_depth(const Vec3& q0, const Vec3& q1, const Vec3& h);

}  // namespace tecido
