#pragma once
/// The hint of a run that went unstable (`tecido run`): the step size the scene's stiffest spring
/// allows for the integrator used, from the stability suite's own theory (theory.h), so that the
/// hint and the suite's measured limits are one definition.
///  - A spring between particles i and j alone oscillates at omega = sqrt(k (1/m_i + 1/m_j))
///    (pair_omega_max; a pinned end has 1/m = 0). The stiffest spring is the one of largest omega.
///  - symplectic and rk4 are stable for h omega <= stable_limit (2, 2 sqrt 2): dt <= limit / omega.
///  - euler and midpoint amplify an undamped oscillation at every step, so no step is stable; the
///    hint is the step at which the run's duration (steps x dt) grows it by at most the suite's
///    amplitude bound (horizon_prediction, the suite's "largest stable step over N periods").
/// An estimate from one spring: springs sharing particles (a cloth) can need a smaller step, and
/// damping, contacts and other forces are left out.
#include "core/scene/scene.h"

#include <cstddef>
#include <optional>
#include <string>

namespace tecido::suites::stability {

struct StepHint {
  int i = 0, j = 0;          ///< the stiffest spring's particles
  double stiffness = 0.0;    ///< its k [N/m]
  double omega = 0.0;        ///< sqrt(k (1/m_i + 1/m_j)) [rad/s]
  bool bounded = true;       ///< symplectic, rk4: a stable step exists; euler, midpoint: a growth bound
  double h_omega = 0.0;      ///< the largest h omega (stable_limit, or horizon_prediction's c)
  double dt_max = 0.0;       ///< h_omega / omega [s]
  double duration = 0.0;     ///< steps x dt of the scene [s] (the growers' horizon)
  double growth_bound = 0.0; ///< the growers' bound on the amplitude's growth over `duration`
};

/// The hint for the scene as it will run (its integrator, dt and steps); none when no spring has
/// a positive omega (no spring, zero stiffness, or both ends pinned).
std::optional<StepHint> stiffest_spring_step(const Scene& scene);

/// One line for stderr, "tecido: hint: ...", naming the integrator, dt_max and the spring (for
/// euler and midpoint also symplectic Euler's stable step, which a long run may need instead).
std::string step_hint_line(const StepHint& hint, const Scene& scene);

}  // namespace tecido::suites::stability
