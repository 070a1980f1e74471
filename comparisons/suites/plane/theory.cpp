#include "comparisons/suites/plane/theory.h"

#include <cmath>

namespace tecido::suites::plane {

double impact_speed(double z0, double vz0, double g) { return std::sqrt(vz0 * vz0 + 2.0 * g * z0); }

double contact_time(double z0, double vz0, double g) { return (vz0 + impact_speed(z0, vz0, g)) / g; }

double rebound_apex(double z0, double k) { return k * k * z0; }

double rebound_flight(double z0, double k, double g) { return 2.0 * k * impact_speed(z0, 0.0, g) / g; }

bool exact_for_constant_acceleration(IntegratorKind k) {
  switch (k) {
    case IntegratorKind::Midpoint:
    case IntegratorKind::RK4: return true;
    case IntegratorKind::Euler:
    case IntegratorKind::Symplectic: return false;
  }
  return false;
}

}  // namespace tecido::suites::plane
