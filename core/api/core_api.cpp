#include <tecido/core.h>

#include "core/api/public_types.h"
#include "core/geometry/ccd/ccd.h"
#include "core/geometry/segment_plane.h"
#include "core/geometry/tri_tri_intersect.h"

namespace tecido::core {

bool tri_tri(const Triangle& a, const Triangle& b) { return tri_tri_intersect(a, b); }

PlaneHit segment_plane(const Rectangle& r, const Vec3& from, const Vec3& to) {
  const SegmentPlaneHit h = ::tecido::segment_plane(api::bounded_plane(r), from, to);
  return PlaneHit{h.hit, h.hit ? h.t : 0.0};
}

Contact ccd(const Motion& m) {
  const CcdAnswer a = ::tecido::ccd(api::ccd_query(m));
  return Contact{a.hit, a.hit ? a.toi : 0.0};
}

}  // namespace tecido::core
