#pragma once
/// Particle state as arrays (seed section 2.1: mass, position, linear velocity, no rotation;
/// an elastic quotient k per particle), in the data-oriented layout of Box2D v3: one array per
/// quantity, indexed by particle id. A pinned particle has inverse mass 0 and never moves.
#include "core/geometry/types.h"

#include <cstdint>
#include <vector>

namespace tecido {

struct Particles {
  std::vector<Vec3> x;              ///< positions [m]
  std::vector<Vec3> v;              ///< velocities [m/s]
  std::vector<double> inv_mass;     ///< 1/m [1/kg]; 0 for pinned particles
  std::vector<double> elasticity;   ///< restitution quotient k in [0, 1] (seed eq. 9)
  std::vector<std::uint8_t> pinned; ///< 1 when the particle is fixed in place

  std::size_t size() const { return x.size(); }

  /// Appends one particle; a pinned particle gets inverse mass 0 and zero velocity.
  void add(const Vec3& position, const Vec3& velocity, double mass, double k, bool is_pinned) {
    x.push_back(position);
    v.push_back(is_pinned ? Vec3::Zero() : velocity);
    inv_mass.push_back(is_pinned || mass <= 0.0 ? 0.0 : 1.0 / mass);
    elasticity.push_back(k);
    pinned.push_back(is_pinned ? 1 : 0);
  }
};

}  // namespace tecido
