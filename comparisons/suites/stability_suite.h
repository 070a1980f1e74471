#pragma once
/// Suite `stability`: the largest stable step of each integrator on an undamped oscillator,
/// found by a deterministic bisection on h, across six decades of stiffness and of mass, against
/// the linear-stability theory (symplectic Euler: h omega < 2; RK4: h omega < 2 sqrt 2; explicit
/// Euler and midpoint: no stable step at all, so their measured growth per period is reported
/// instead); then the extremes: coordinates offset by 1e6..1e8 m, mass ratios of 1e6 across a
/// spring, near-zero rest lengths, a particle resting on a plane for 1e5 steps, and steps of up
/// to 10 s toward a thin bounded plane.
///
/// "Stable at h" (the definition every number here uses): a run of `periods` periods of the
/// exact motion (2 pi / omega each) at step h stays finite (no NaN/Inf, Simulation::instability)
/// and the displacement from equilibrium never exceeds `amplitude_bound` times the initial one.
/// Both numbers come from data/tolerances.json (/stability/periods, /stability/amplitude_bound).
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"
#include "core/dynamics/integrator.h"
#include "core/scene/scene.h"

#include <functional>

namespace tecido::suites {

/// Result of find_max_stable_step.
struct StableStep {
  bool found = false;       ///< a stable h was met (false: every h tried was unstable)
  double h = 0.0;           ///< largest h found stable (the lower end of the final bracket)
  double h_unstable = 0.0;  ///< smallest h found unstable (upper end; 0 if none met)
  int runs = 0;             ///< calls of the predicate
};

/// Largest h for which stable(h) holds, assuming stability is monotone in h. Deterministic:
/// starting at h_start, doubles while stable (at most max_doublings times) or halves while
/// unstable (at most max_halvings times) to bracket the limit, then bisects the bracket
/// [stable lo, unstable hi] at the arithmetic midpoint until hi - lo <= rel_tol * lo.
StableStep find_max_stable_step(const std::function<bool(double h)>& stable, double h_start, double rel_tol,
                                int max_doublings = 40, int max_halvings = 40);

/// |R(i c)|: the factor by which one step of the integrator multiplies the norm of the state
/// (x, v / omega) of x'' = -omega^2 x at c = h omega (euler, midpoint, rk4: their update is a
/// scaled rotation). For symplectic Euler, whose update is not normal, the spectral radius
/// (1 for c <= 2).
double amplification(IntegratorKind k, double c);

/// One run of the oscillator of the `stability` suite: a particle of mass m on a zero-rest-length
/// spring of stiffness ks to a pinned particle at the origin (force -ks x: exactly linear in every
/// direction), released at rest 1 m away along x.
struct OscillatorRun {
  bool finite = true;        ///< no NaN/Inf
  bool bounded = true;       ///< |x| never exceeded the amplitude bound
  long long steps = 0;       ///< steps done (a run stops at the first bad or unbounded step)
  double growth_per_step = 1.0;  ///< (r_n / r_0)^(1/n), r = sqrt(|x|^2 + |v|^2 / omega^2)
};
OscillatorRun run_oscillator(IntegratorKind k, double ks, double m, double h, double periods, double amplitude_bound);

/// Largest stable h * omega of the oscillator (see the definition above), bisected on h to a
/// relative width rel_tol, starting from h = 1 / omega. found = false: no stable step.
StableStep oscillator_max_step(IntegratorKind k, double ks, double m, double periods, double amplitude_bound,
                               double rel_tol);

/// The suite as a sweep (comparisons/suites/sweep.h): one case per grid cell's bisection, per
/// horizon, per growth run and per group of extremes.
Sweep stability_sweep(const SuiteContext& ctx);
SuiteResult run_stability_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
