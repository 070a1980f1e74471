#pragma once
/// The runs the `stability` suite measures: the oscillator (a particle on a zero-rest-length spring
/// to a pinned particle), any scene run under an amplitude bound, and the deterministic search for
/// the largest stable step.
#include "core/dynamics/integrator.h"
#include "core/dynamics/particles.h"
#include "core/scene/scene.h"

#include <functional>

namespace tecido::suites::stability {

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

/// The oscillator's scene: a pinned particle at the origin and a particle of mass m released at rest
/// at (1, 0, 0), joined by a zero-rest-length spring of stiffness ks; integrator k, step h.
Scene oscillator_scene(IntegratorKind k, double ks, double m, double h);

/// One run of the oscillator: a particle of mass m on a zero-rest-length spring of stiffness ks to
/// a pinned particle at the origin (force -ks x: exactly linear in every direction), released at
/// rest 1 m away along x, for ceil(periods 2 pi / (omega h)) steps or until |x| exceeds
/// amplitude_bound or a step is not finite.
struct OscillatorRun {
  bool finite = true;            ///< no NaN/Inf
  bool bounded = true;           ///< |x| never exceeded the amplitude bound
  long long steps = 0;           ///< steps done (a run stops at the first bad or unbounded step)
  long long unstable_step = 0;   ///< the step that was not finite (0 when finite)
  double growth_per_step = 1.0;  ///< (r_n / r_0)^(1/n), r = sqrt(|x|^2 + |v|^2 / omega^2); +inf when not finite
};
OscillatorRun run_oscillator(IntegratorKind k, double ks, double m, double h, double periods, double amplitude_bound);

/// Largest stable h of the oscillator ("stable at h": a run of `periods` periods stays finite and
/// within the amplitude bound), bisected on h to a relative width rel_tol, starting from h = 1 /
/// omega. found = false: no stable step down to 2^-max_halvings / omega.
StableStep oscillator_max_step(IntegratorKind k, double ks, double m, double periods, double amplitude_bound,
                               double rel_tol, int max_doublings = 40, int max_halvings = 40);

/// A scene stepped up to n times, stopping at the first non-finite step or when amp(particles)
/// exceeds limit.
struct BoundedRun {
  bool finite = true;
  bool bounded = true;
  long long steps = 0;
  long long unstable_step = 0;  ///< the step that was not finite (0 when finite)
  double max_amp = 0.0;
};
BoundedRun run_bounded(const Scene& scene, long long n, const std::function<double(const Particles&)>& amp,
                       double limit);

/// Steps of `periods` periods of 2 pi / omega at step h, rounded up.
long long steps_for(double periods, double omega, double h);

}  // namespace tecido::suites::stability
