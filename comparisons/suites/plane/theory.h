#pragma once
/// The `plane` suite's predicted values: a particle in free fall over the floor z = 0 under gravity
/// g along -z, and its rebound (seed eq. 9: the normal velocity mirrored and scaled by k).
#include "core/dynamics/integrator.h"

namespace tecido::suites::plane {

/// The first time t > 0 at which z0 + vz0 t - g t^2 / 2 = 0 (z0 >= 0, g > 0) [s].
double contact_time(double z0, double vz0, double g);
/// The speed at that time, |vz0 - g t| = sqrt(vz0^2 + 2 g z0) [m/s].
double impact_speed(double z0, double vz0, double g);
/// The apex of the first rebound from rest at z0 with restitution k: (k v)^2 / 2g = k^2 z0 [m].
double rebound_apex(double z0, double k);
/// How long the first rebound from rest at z0 stays aloft: 2 k sqrt(2 g z0) / g [s].
double rebound_flight(double z0, double k, double g);
/// True when the integrator reproduces motion under constant acceleration exactly (its local error
/// vanishes for a quadratic path: midpoint and RK4), so that its contact time's error is the
/// bisection's alone; explicit and symplectic Euler add an O(h) position error of their own.
bool exact_for_constant_acceleration(IntegratorKind k);

}  // namespace tecido::suites::plane
