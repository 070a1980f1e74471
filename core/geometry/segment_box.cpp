#include "core/geometry/segment_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido {

int nearest_box_face(const Vec3& q, const Vec3& h) {
  int best = 0;
  double best_gap = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i) {
    const double gap = h[i] - std::abs(q[i]);
    if (gap < best_gap) {
      best_gap = gap;
      best = 2 * i + (q[i] >= 0.0 ? 1 : 0);
    }
  }
  return best;
}

Vec3 project_on_box_face(const Vec3& q, const Vec3& h, int face) {
  Vec3 p;
  for (int i = 0; i < 3; ++i) p[i] = std::clamp(q[i], -h[i], h[i]);
  const int axis = face / 2;
  p[axis] = (face & 1) ? h[axis] : -h[axis];
  return p;
}

BoxEntry segment_enters_box(const Vec3& q0, const Vec3& q1, const Vec3& h) {
  const Vec3 d = q1 - q0;
  double lo = -std::numeric_limits<double>::infinity(), hi = std::numeric_limits<double>::infinity();
  int face = -1;
  bool empty = false;
  for (int i = 0; i < 3 && !empty; ++i) {
    if (d[i] == 0.0) {
      empty = !(std::abs(q0[i]) < h[i]);  // never strictly between the two faces of this axis
      continue;
    }
    // Open interval of s where -h < q0 + s d < h.
    double a = (-h[i] - q0[i]) / d[i], b = (h[i] - q0[i]) / d[i];
    if (a > b) std::swap(a, b);
    if (a > lo) {
      lo = a;
      face = 2 * i + (d[i] < 0.0 ? 1 : 0);  // moving down the axis enters through its + face
    }
    hi = std::min(hi, b);
  }
  if (!empty && lo < hi && lo < 1.0 && hi > 0.0) {
    // Starting inside (only an initial state can): out through the nearest face.
    if (face < 0 || inside_box(q0, h)) face = nearest_box_face(q0, h);
    return BoxEntry{true, std::clamp(lo, 0.0, 1.0), face};
  }
  if (inside_box(q1, h)) return BoxEntry{true, 1.0, nearest_box_face(q1, h)};
  return BoxEntry{};
}

double segment_box_depth(const Vec3& q0, const Vec3& q1, const Vec3& h) {
  if (!segment_enters_box(q0, q1, h).hit && !inside_box(q0, h)) return 0.0;
  const SegmentDepthProfile depth(q0, q1, h);
  double best = depth.at(0.0);
  depth.for_each_candidate([&](double s) { best = std::max(best, depth.at(s)); });
  return std::max(best, 0.0);
}

}  // namespace tecido
