#include "reference/plane_box.h"

#include <algorithm>
#include <sstream>

namespace tecido::reference {

namespace {
std::string num(double x) {
  std::ostringstream s;
  s.precision(6);
  s << x;
  return s.str();
}
}  // namespace

PlaneBox plane_box(const Scene& scene, std::size_t k, double thickness, double collision_margin) {
  const BoundedPlane& pl = scene.planes[k];
  const Particles& p = scene.particles;
  bool pos = false, neg = false;
  for (std::size_t i = 0; i < p.size(); ++i) {
    if (p.pinned[i]) continue;
    const double s = pl.side(p.x[i]);
    pos = pos || s > 0.0;
    neg = neg || s < 0.0;
  }
  PlaneBox b;
  const double t = thickness;
  double centre_offset = 0.0;  // along the normal
  b.contact_offset = collision_margin;
  if (pos && !neg) {
    centre_offset = -0.5 * t;
  } else if (neg && !pos) {
    centre_offset = 0.5 * t;
  } else {
    b.contact_offset = 0.5 * t + collision_margin;
    b.note = "two-sided plane " + std::to_string(k) + ": free particles start on both sides, so the static box (thickness " +
             num(t) + " m) is centred on the plane and its faces stand " + num(0.5 * t) + " m off it";
  }
  const double hx = std::max(pl.half_extents.x(), 1e-9), hy = std::max(pl.half_extents.y(), 1e-9);
  b.half_extents = Vec3(hx, hy, 0.5 * t);
  // btBoxShape keeps its outer faces at the half extents whatever the margin; a margin larger
  // than a half extent would round the box, so keep it below every half extent.
  b.shape_margin = std::min({0.04, 0.5 * hx, 0.5 * hy, 0.25 * t});
  b.axes = {pl.forward, pl.right(), pl.normal};
  b.centre = pl.position + centre_offset * pl.normal;
  return b;
}

}  // namespace tecido::reference
