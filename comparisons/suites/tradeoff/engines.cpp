#include "comparisons/suites/tradeoff/engines.h"

#include "comparisons/engines/dynamics_engines.h"
#include "comparisons/suites/tradeoff/outside_engines.h"

#include <fmt/format.h>

#include <algorithm>
#include <exception>

namespace tecido::suites::tradeoff {

namespace {

/// reference::run_guarded taking `chunk` steps per advance() call, the stray check after each.
reference::GuardedRun run_chunked(engines::DynamicsEngine& e, const std::vector<Vec3>& x0, long long steps,
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
  std::unique_ptr<engines::DynamicsEngine> e;
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

namespace {

/// Bullet's ranges by engine (bullet_dynamics_engines.h names them by kind).
void set_bullet_range(TradeoffEngine& e, const BulletRange& r) {
  if (e.name.rfind("bullet-classic", 0) == 0) e.max_n = r.max_side_classic;
  else if (e.name.rfind("bullet-deformable-implicit", 0) == 0) e.max_n = r.max_side_implicit;
  else e.max_n = r.max_side_explicit;
  e.max_steps = r.max_steps;
}

}  // namespace

TradeoffEngine tradeoff_engine(const engines::DynamicsEntry& entry, const Settings& s) {
  TradeoffEngine e;
  e.name = entry.name;
  e.evaluations_per_step = entry.evaluations_per_step;
  e.make = entry.make;
  switch (entry.source) {
    case engines::DynamicsSource::Core: e.name = "core-" + entry.name; break;
    case engines::DynamicsSource::Bullet: set_bullet_range(e, s.bullet); break;
    case engines::DynamicsSource::Outside:
      e.door = entry.outside_engine->door();
      e.door_chunk = kOutsideChunk;
      e.max_n = s.outside.max_side;
      e.max_steps = s.outside.max_steps;
      break;
  }
  return e;
}

TradeoffEngine core_tradeoff_engine(IntegratorKind kind) {
  return tradeoff_engine(engines::core_dynamics_entry(kind), Settings{});
}

std::vector<TradeoffEngine> tradeoff_engines(const Settings& s, const SuiteContext* ctx) {
  engines::DynamicsSources sources;
  sources.core = sources.bullet = sources.outside = true;
  std::vector<TradeoffEngine> out;
  for (const engines::DynamicsEntry& d : engines::dynamics_engines(sources, ctx ? ctx->outside.get() : nullptr, s.classic))
    if (d.source != engines::DynamicsSource::Outside || ctx->selects(d.name)) out.push_back(tradeoff_engine(d, s));
  return out;
}

bool skipped(const TradeoffEngine& e, int n, std::size_t j) {
  return (e.max_n > 0 && n > e.max_n) || (e.max_steps > 0 && j >= static_cast<std::size_t>(e.max_steps));
}

}  // namespace tecido::suites::tradeoff
