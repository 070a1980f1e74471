#include "comparisons/suites/tradeoff/engines.h"

#include "comparisons/engines/core_dynamics.h"
#ifdef TECIDO_HAVE_REFERENCE
#include "comparisons/suites/tradeoff/bullet_engines.h"
#endif

#include <exception>

namespace tecido::suites::tradeoff {

reference::GuardedRun TradeoffEngine::run_guarded(const Scene& scene, double h, double seconds, double stray_limit) const {
  Scene s = scene;
  s.dt = h;
  std::unique_ptr<reference::DynamicsEngine> e;
  try {
    e = make(s);
  } catch (const std::exception& ex) {
    reference::GuardedRun r;
    r.reason = std::string("not built: ") + ex.what();
    return r;
  }
  return reference::run_guarded(*e, scene.particles.x, reference::fixed_time_steps(seconds, h), stray_limit);
}

std::optional<std::vector<Vec3>> TradeoffEngine::run(const Scene& scene, double h, double seconds) const {
  return run_guarded(scene, h, seconds).x;
}

TradeoffEngine core_tradeoff_engine(IntegratorKind kind) {
  TradeoffEngine e;
  e.name = std::string("core-") + integrator_name(kind);
  e.evaluations_per_step = evaluations_per_step(kind);
  e.make = [kind](const Scene& scene) -> std::unique_ptr<reference::DynamicsEngine> {
    Scene s = scene;
    s.integrator = kind;
    return std::make_unique<engines::CoreDynamics>(s);
  };
  return e;
}

std::vector<TradeoffEngine> tradeoff_engines(const Settings& s) {
  std::vector<TradeoffEngine> engines;
  for (IntegratorKind k : {IntegratorKind::Euler, IntegratorKind::Symplectic, IntegratorKind::Midpoint, IntegratorKind::RK4})
    engines.push_back(core_tradeoff_engine(k));
#ifdef TECIDO_HAVE_REFERENCE
  for (TradeoffEngine& e : bullet_tradeoff_engines(s)) engines.push_back(std::move(e));
#else
  (void)s;
#endif
  return engines;
}

bool skipped(const TradeoffEngine& e, int n, std::size_t j) {
  return (e.max_n > 0 && n > e.max_n) || (e.max_steps > 0 && j >= static_cast<std::size_t>(e.max_steps));
}

}  // namespace tecido::suites::tradeoff
