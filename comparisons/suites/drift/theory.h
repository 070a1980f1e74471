#pragma once
/// What theory predicts for the `drift` suite's measurements.
///
/// Angular momentum L = sum m x x v under central, pairwise spring forces (sum x_i x f_i = 0):
///  - symplectic Euler conserves it exactly: L_{n+1} = sum m (x_n + h v_{n+1}) x v_{n+1}
///    = sum m x_n x v_{n+1} = L_n + h sum x_n x f(x_n) = L_n;
///  - an explicit Runge-Kutta method with tableau (a, b) changes it, per step, by
///    h^2 sum_ij (b_i b_j - b_i a_ij - b_j a_ji) sum_particles V_i x F_j, V_i and F_j the stage
///    velocities and forces (Cooper 1987: the method conserves quadratic invariants exactly when
///    the bracket vanishes; for explicit Euler it is h^2 sum v x f, never zero in general).
/// Contact: a body released at rest from height z0 under gravity g first reaches the floor at
/// sqrt(2 z0 / g). Load: a Hooke cloth's sag is proportional to its load, Bullet's position-based
/// links' sag does not depend on it (reference/klst_calibration.h), so at load_factor times the
/// calibration load the classic body sags 1 / load_factor as far as core.
#include "core/dynamics/integrator.h"
#include "core/dynamics/spring.h"
#include "core/geometry/types.h"

#include <optional>
#include <vector>

namespace tecido::suites::drift {

/// An explicit Runge-Kutta method's Butcher tableau: stage i uses a[i][j], j < i; weights b.
struct Tableau {
  std::vector<std::vector<double>> a;
  std::vector<double> b;
};

/// The tableau of core's explicit Euler (1 stage), midpoint (2) and RK4 (4), as
/// core/dynamics/integrator.h describes them; nothing for symplectic Euler (a partitioned method).
std::optional<Tableau> runge_kutta_tableau(IntegratorKind kind);

/// Whether `kind` conserves angular momentum exactly under central forces (symplectic Euler only).
bool conserves_angular_momentum(IntegratorKind kind);

/// Cooper's change of angular momentum over one step h of the method `t` from (x, v), for
/// particles of inverse masses `inv_mass` (every one free) joined by `springs` (no other force):
/// h^2 sum_ij (b_i b_j - b_i a_ij - b_j a_ji) sum_k V_i,k x F_j,k with the stages computed here.
Vec3 angular_momentum_change(const Tableau& t, const std::vector<Spring>& springs, const std::vector<double>& inv_mass,
                             const std::vector<Vec3>& x, const std::vector<Vec3>& v, double h);

/// sqrt(2 z0 / g): when a body released at rest z0 above the floor reaches it [s].
double fall_time(double z0, double g);

/// The classic body's sag over core's at `load_factor` times the load both were matched at:
/// 1 / load_factor.
double classic_sag_ratio(double load_factor);

}  // namespace tecido::suites::drift
