#include "core/geometry/segment_box_separation.h"

#include "core/geometry/segment_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tecido {

double segment_box_deepest(const Vec3& q0, const Vec3& q1, const Vec3& h) {
  const SegmentDepthProfile depth(q0, q1, h);
  double best_s = 0.5, best = depth.at(0.5);
  depth.for_each_candidate([&](double s) {
    const double v = depth.at(s);
    if (v > best) best = v, best_s = s;
  });
  return best_s;
}

SegmentBoxSeparation segment_box_separation(const Vec3& q0, const Vec3& q1, const Vec3& h) {
  SegmentBoxSeparation out;
  const Vec3 d = q1 - q0;
  Vec3 axes[6];
  int n_axes = 0;
  for (int k = 0; k < 3; ++k) axes[n_axes++] = Vec3::Unit(k);
  for (int k = 0; k < 3; ++k) {
    const Vec3 c = d.cross(Vec3::Unit(k));
    const double len = c.norm();
    if (len > 1e-12 * d.norm()) axes[n_axes++] = c / len;
  }
  double best = std::numeric_limits<double>::infinity(), gap = 0.0;
  for (int a = 0; a < n_axes; ++a) {
    const Vec3& u = axes[a];
    const double p0 = u.dot(q0), p1 = u.dot(q1);
    const double r = h.x() * std::abs(u.x()) + h.y() * std::abs(u.y()) + h.z() * std::abs(u.z());
    const double up = r - std::min(p0, p1), down = std::max(p0, p1) + r;  // push along +u, along -u
    gap = std::max(gap, std::max(-up, -down));
    for (int sign : {1, -1}) {
      const double overlap = sign > 0 ? up : down;
      if (!(overlap < best)) continue;
      best = overlap;
      out.normal = sign * u;
      const bool perpendicular = std::abs(p1 - p0) <= 1e-12 * (std::abs(p0) + std::abs(p1) + r);
      out.s = perpendicular ? -1.0 : ((sign > 0) == (p0 < p1) ? 0.0 : 1.0);
    }
  }
  out.cuts = segment_box_depth(q0, q1, h) > 0.0;
  out.overlap = out.cuts ? std::max(best, 0.0) : 0.0;
  out.clearance = out.cuts ? 0.0 : gap;
  if (out.s < 0.0) out.s = segment_box_deepest(q0, q1, h);
  return out;
}

}  // namespace tecido
