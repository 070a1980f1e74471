#pragma once
/// Impulse response of a particle hitting a moving surface: the seed's eq. 9 (plane_contact.h)
/// applied to the velocity relative to the surface, v_rel = v - u, where u is the surface's
/// velocity at the contact point; the result is v = v_rel' + u. A static surface (u = 0) gives
/// eq. 9 exactly. The contact's elastic quotient is the obstacle's when it has one, else the
/// particle's k (docs/design.md section 3, "obstacles").
#include "core/dynamics/plane_contact.h"

#include <optional>

namespace tecido {

/// Applies eq. 9 to v relative to surface velocity u for a contact with outward unit normal n
/// (pointing from the surface towards the particle). A particle already separating
/// (v_rel . n > 0, possible when a moving surface or the integrator's curved path has turned it
/// around by the end of the bracket) is left alone: nothing (no branch ran) is returned. One
/// sliding along the surface (v_rel . n = 0, e.g. onto the next coplanar triangle of a mesh)
/// gets the static branch, so it rests there.
inline std::optional<ContactKind> respond_to_moving_contact(Vec3& v, const Vec3& u, const Vec3& n, double k,
                                                            double friction, const ContactSettings& s) {
  Vec3 rel = v - u;
  if (!(rel.dot(n) <= 0.0)) return std::nullopt;
  const ContactKind kind = respond_to_contact(rel, n, k, friction, s);
  v = rel + u;
  return kind;
}

}  // namespace tecido
