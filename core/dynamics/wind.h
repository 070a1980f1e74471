#pragma once
/// Wind as a force on every free particle [N per particle].
/// Constant: the vector `force`. Swirl: constant magnitude |force|, direction circling the
/// unit `axis` at `rate` [rad/s] starting from `phase` [rad]:
///   w(t) = |force| (cos(rate t + phase) e1 + sin(rate t + phase) e2),
/// where (e1, e2, axis) is right-handed and e1 is the component of `force` orthogonal to the
/// axis (or any orthogonal unit vector when force is parallel to it). The phase is drawn from
/// the scene's seed when the scene does not give it. Random (optional, with swirl): the heading
/// also carries the random offset of random_wind.h (the seed's random wind, fig. 15):
///   w(t) = |force| (cos(rate t + phase + beta(t)) e1 + sin(...) e2).
#include "core/dynamics/random_wind.h"
#include "core/geometry/types.h"

#include <cmath>
#include <memory>

namespace tecido {

struct Wind {
  Vec3 force = Vec3::Zero();
  bool swirl = false;
  Vec3 axis = Vec3::UnitZ();
  double rate = 0.0;
  double phase = 0.0;
  /// Only read when swirl is set. Immutable once made (copies of a scene share the knot table).
  std::shared_ptr<const RandomHeading> random{};

  /// The wind force at time t.
  Vec3 at(double t) const {
    if (!swirl) return force;
    const Vec3 ax = axis.normalized();
    Vec3 e1 = force - ax * ax.dot(force);
    if (e1.norm() < 1e-300) e1 = ax.unitOrthogonal();
    e1.normalize();
    const Vec3 e2 = ax.cross(e1);
    const double th = rate * t + phase + (random ? random->offset(t) : 0.0);
    return force.norm() * (std::cos(th) * e1 + std::sin(th) * e2);
  }
};

}  // namespace tecido
