#include "comparisons/suites/tradeoff/engines.h"

#include "comparisons/engines/core_dynamics.h"
#include "comparisons/suites/tradeoff/bullet_engines.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

namespace tecido::suites::tradeoff {

namespace {

/// reference::run_guarded taking `chunk` steps per advance() call, the stray check after each.
reference::GuardedRun run_chunked(reference::DynamicsEngine& e, const std::vector<Vec3>& x0, long long steps,
                                  double stray_limit, long long chunk) {
  reference::GuardedRun r;
  for (long long done = 0; done < steps;) {
    const long long k = std::min(chunk, steps - done);
    const bool finite = e.advance(k);
    done += k;
    if (finite && !reference::strayed(e.positions(), x0, stray_limit)) continue;
    r.failed_at_step = done;
    r.reason = (finite ? fmt::format("a node more than {:g} m from its start", stray_limit) : "non-finite state") +
               " by step " + std::to_string(done);
    return r;
  }
  r.x = e.positions();
  return r;
}

}  // namespace

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
  const long long steps = reference::fixed_time_steps(seconds, h);
  if (door_chunk > 0) return run_chunked(*e, scene.particles.x, steps, stray_limit, door_chunk);
  return reference::run_guarded(*e, scene.particles.x, steps, stray_limit);
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
  for (TradeoffEngine& e : bullet_tradeoff_engines(s)) engines.push_back(std::move(e));
  return engines;
}

bool skipped(const TradeoffEngine& e, int n, std::size_t j) {
  return (e.max_n > 0 && n > e.max_n) || (e.max_steps > 0 && j >= static_cast<std::size_t>(e.max_steps));
}

}  // namespace tecido::suites::tradeoff
