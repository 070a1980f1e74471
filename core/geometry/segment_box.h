#pragma once
/// A particle's path against a solid box, in the box's local frame (axes along its edges, origin
/// at its centre, half extents h): a slab test (Kay and Kajiya 1986) on the open box
/// |q_i| < h_i. For a moving box the start and end points are each taken into the box's frame
/// at their own time, so the relative motion is the straight segment q0 -> q1 (exact for a
/// translating box; for a rotating one the relative path is linearised over the (sub-)step).
/// Faces are numbered 2 i + (0 for -h_i, 1 for +h_i), i = 0, 1, 2 (x, y, z).
#include "core/geometry/types.h"

#include <algorithm>
#include <cmath>
#include <limits>

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

/// The depth of the point q0 + s (q1 - q0) in the box, min_i (h_i - |q_i(s)|), as the minimum of
/// six linear pieces h_i -+ q_i(s): concave and piecewise linear in s, so its maximum over
/// [0, 1] is at an end or where two pieces cross. Those (at most 17) candidates decide every
/// question about the segment's deepest point (segment_box_depth, segment_box_deepest).
class SegmentDepthProfile {
 public:
  SegmentDepthProfile(const Vec3& q0, const Vec3& q1, const Vec3& h) {
    const Vec3 d = q1 - q0;
    for (int i = 0; i < 3; ++i)
      for (int k = 0; k < 2; ++k) {
        const double sigma = k ? 1.0 : -1.0;
        c0_[2 * i + k] = h[i] - sigma * q0[i];
        c1_[2 * i + k] = -sigma * d[i];
      }
  }
  double at(double s) const {
    double m = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 6; ++k) m = std::min(m, c0_[k] + c1_[k] * s);
    return m;
  }
  /// Calls f(s) for s = 0, s = 1, then for every crossing of two pieces strictly inside (0, 1),
  /// pairs in lexicographic order.
  template <class F>
  void for_each_candidate(F&& f) const {
    f(0.0);
    f(1.0);
    for (int a = 0; a < 6; ++a)
      for (int b = a + 1; b < 6; ++b) {
        if (c1_[a] == c1_[b]) continue;
        const double s = (c0_[b] - c0_[a]) / (c1_[a] - c1_[b]);
        if (s > 0.0 && s < 1.0) f(s);
      }
  }

 private:
  double c0_[6], c1_[6];  ///< piece k: c0_[k] + c1_[k] s
};

/// The largest depth of the segment q0 -> q1 inside the box over s in [0, 1]
/// (SegmentDepthProfile: how far its deepest point is from the nearest face), or 0 when the
/// segment does not enter the open box.
double segment_box_depth(const Vec3& q0, const Vec3& q1, const Vec3& h);

}  // namespace tecido
