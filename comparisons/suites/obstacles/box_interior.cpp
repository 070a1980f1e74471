#include "comparisons/suites/obstacles/box_interior.h"

#include <algorithm>
#include <limits>

namespace tecido::suites::obstacles {

namespace {

/// The six faces' distances along the segment as lines c + d s (inside when all are > 0).
struct Lines {
  std::array<double, 6> c, d;
};

Lines face_lines(const Vec3& q0, const Vec3& q1, const Vec3& half) {
  Lines l{};
  for (int i = 0; i < 3; ++i) {
    const double dq = q1[i] - q0[i];
    l.c[2 * i] = half[i] - q0[i], l.d[2 * i] = -dq;      // half - q
    l.c[2 * i + 1] = half[i] + q0[i], l.d[2 * i + 1] = dq;  // half + q
  }
  return l;
}

double depth_at(const Lines& l, double s) {
  double m = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 6; ++k) m = std::min(m, l.c[k] + l.d[k] * s);
  return m;
}

}  // namespace

double point_box_depth(const Vec3& x, const OrientedBox& box) {
  const Vec3 q = box.rotation.transpose() * (x - box.center);
  return std::min({box.half.x() - std::abs(q.x()), box.half.y() - std::abs(q.y()), box.half.z() - std::abs(q.z())});
}

double segment_box_interior_depth(const Vec3& p0, const Vec3& p1, const OrientedBox& box) {
  const Vec3 q0 = box.rotation.transpose() * (p0 - box.center);
  const Vec3 q1 = box.rotation.transpose() * (p1 - box.center);
  const Lines l = face_lines(q0, q1, box.half);
  double best = std::max(depth_at(l, 0.0), depth_at(l, 1.0));
  for (int a = 0; a < 6; ++a)
    for (int b = a + 1; b < 6; ++b) {
      const double dd = l.d[a] - l.d[b];
      if (dd == 0.0) continue;
      const double s = (l.c[b] - l.c[a]) / dd;
      if (s > 0.0 && s < 1.0) best = std::max(best, depth_at(l, s));
    }
  return best;
}

int springs_through_box(const std::vector<Vec3>& x, const std::vector<std::array<int, 2>>& springs,
                        const OrientedBox& box, double min_depth, double* deepest) {
  int count = 0;
  double worst = 0.0;
  for (const auto& [i, j] : springs) {
    const double d = segment_box_interior_depth(x[i], x[j], box);
    if (d > min_depth) {
      ++count;
      worst = std::max(worst, d);
    }
  }
  if (deepest) *deepest = worst;
  return count;
}

}  // namespace tecido::suites::obstacles
