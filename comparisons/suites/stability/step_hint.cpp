#include "comparisons/suites/stability/step_hint.h"

#include "comparisons/suites/stability/settings.h"
#include "comparisons/suites/stability/theory.h"

#include <fmt/format.h>

#include <cmath>

namespace tecido::suites::stability {

namespace {

/// 1 / inv_mass, +inf for a pinned particle (inv_mass 0), which pair_omega_max turns back into 0.
double mass_of(double inv_mass) { return 1.0 / inv_mass; }

}  // namespace

std::optional<StepHint> stiffest_spring_step(const Scene& scene) {
  std::optional<StepHint> best;
  const std::vector<double>& inv = scene.particles.inv_mass;
  for (const Spring& s : scene.forces.springs) {
    const double omega = pair_omega_max(s.stiffness, mass_of(inv[s.i]), mass_of(inv[s.j]));
    if (!(omega > 0.0) || !std::isfinite(omega) || (best && omega <= best->omega)) continue;
    best = StepHint{};
    best->i = s.i;
    best->j = s.j;
    best->stiffness = s.stiffness;
    best->omega = omega;
  }
  if (!best) return best;
  best->duration = static_cast<double>(scene.steps) * scene.dt;
  best->h_omega = stable_limit(scene.integrator);
  best->bounded = std::isfinite(best->h_omega);
  if (!best->bounded) {
    best->growth_bound = Settings{}.amplitude_bound;
    const double periods = best->duration * best->omega / (2.0 * kPi);
    best->h_omega = horizon_prediction(scene.integrator, periods, best->growth_bound);
  }
  best->dt_max = best->h_omega / best->omega;
  return best;
}

std::string step_hint_line(const StepHint& h, const Scene& scene) {
  const char* name = integrator_name(scene.integrator);
  const std::string spring =
      fmt::format("the stiffest spring (particles {} and {}, k = {:.6g} N/m, omega = sqrt(k (1/m_i + 1/m_j)) = {:.6g} rad/s)",
                  h.i, h.j, h.stiffness, h.omega);
  if (h.bounded)
    return fmt::format("tecido: hint: {} is stable on {} for dt <= {:.6g} s (h omega <= {:.6g}); this run used dt = {:.6g} s",
                       name, spring, h.dt_max, h.h_omega, scene.dt);
  // The growers' step can be absurdly small for a long run: name the step a stable method allows too.
  return fmt::format("tecido: hint: {} amplifies an undamped spring at every step; on {} it grows at most {:g}x over this "
                     "run's {:.6g} s for dt <= {:.6g} s (symplectic is stable for dt <= {:.6g} s); this run used dt = {:.6g} s",
                     name, spring, h.growth_bound, h.duration, h.dt_max,
                     stable_limit(IntegratorKind::Symplectic) / h.omega, scene.dt);
}

}  // namespace tecido::suites::stability
