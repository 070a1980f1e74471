#pragma once
/// Impulse response of a particle hitting a bounded plane (seed section 3.1.1, eq. 9).
/// The velocity is split into vn (along the normal) and vt. If |vn| exceeds the static
/// threshold the contact is elastic: vn is mirrored and scaled by the particle's k,
/// v' = vt - k vn. Otherwise it is static: vn is cancelled (no k), and friction acts on vt:
/// a large vt (|vt| > tangential threshold) is scaled by (1 - mu), a small one is zeroed.
#include "core/geometry/bounded_plane.h"

namespace tecido {

struct ContactSettings {
  double static_threshold = 0.01;      ///< |vn| at or below this [m/s] is a static contact (seed: 0.01)
  double tangential_threshold = 0.01;  ///< |vt| at or below this [m/s] is zeroed in static contact
  /// Bisection stops when the bracket on the time of contact is at most this wide [s];
  /// <= 0 means the default, dt * 2^-20.
  double bisection_tolerance = 0.0;
  int max_events_per_step = 256;  ///< contact events (bisections) per step before the cap is reported
};

enum class ContactKind { Elastic, Static };

/// Applies eq. 9 to v for a contact with a plane of unit normal n; returns which branch ran.
inline ContactKind respond_to_contact(Vec3& v, const Vec3& n, double k, double friction, const ContactSettings& s) {
  const Vec3 vn = n * n.dot(v);
  Vec3 vt = v - vn;
  if (vn.norm() > s.static_threshold) {
    v = vt - k * vn;
    return ContactKind::Elastic;
  }
  v = vt.norm() > s.tangential_threshold ? Vec3((1.0 - friction) * vt) : Vec3::Zero();
  return ContactKind::Static;
}

}  // namespace tecido
