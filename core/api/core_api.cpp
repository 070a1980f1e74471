#include <tecido/core.h>

#include "core/api/mesh_arguments.h"
#include "core/api/public_types.h"
#include "core/cloth/continuous_self_collision.h"
#include "core/cloth/self_collision.h"
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

std::vector<FacePair> self_collisions(const std::vector<Vec3>& V, const Faces& F) {
  api::check_mesh("tecido::core::self_collisions", V, F);
  return self_collision_pairs(V, F);
}

SelfContacts continuous_self_collisions(const std::vector<Vec3>& V0, const std::vector<Vec3>& V1, const Faces& F) {
  api::check_motion_mesh("tecido::core::continuous_self_collisions", V0, V1, F);
  return api::self_contacts(continuous_self_collision(V0, V1, F));
}

}  // namespace tecido::core
