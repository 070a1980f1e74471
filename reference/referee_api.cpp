#include <tecido/referee.h>

#include "core/api/mesh_arguments.h"
#include "core/api/public_types.h"
#include "reference/exact_ccd.h"
#include "reference/exact_referee.h"
#include "reference/exact_self_contacts.h"

namespace tecido::referee {

bool tri_tri(const Triangle& a, const Triangle& b) { return reference::exact_tri_tri(a, b); }

PlaneHit segment_plane(const Rectangle& r, const Vec3& from, const Vec3& to) {
  const reference::ExactSegmentPlane e = reference::exact_segment_plane(api::bounded_plane(r), from, to);
  return PlaneHit{e.hit, e.hit ? e.t : 0.0};
}

ExactContact ccd(const Motion& m) {
  const reference::ExactCcd e = reference::exact_ccd(api::ccd_query(m));
  return ExactContact{e.hit, e.toi, e.toi_lo, e.toi_hi, e.toi_exact};
}

SelfContacts continuous_self_collisions(const std::vector<Vec3>& V0, const std::vector<Vec3>& V1, const Faces& F,
                                        int threads) {
  api::check_motion_mesh("tecido::referee::continuous_self_collisions", V0, V1, F);
  if (threads < 1)
    throw std::invalid_argument("tecido::referee::continuous_self_collisions: threads must be >= 1, got " +
                                std::to_string(threads));
  return api::self_contacts(reference::exact_self_contacts(V0, V1, F, threads));
}

}  // namespace tecido::referee
