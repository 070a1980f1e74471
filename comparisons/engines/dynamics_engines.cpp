#include "comparisons/engines/dynamics_engines.h"

#include "comparisons/engines/bullet_dynamics_engines.h"
#include "comparisons/engines/core_dynamics.h"

#include <stdexcept>

namespace tecido::engines {

namespace {

double claimed_core_order(IntegratorKind kind) {
  switch (kind) {
    case IntegratorKind::Euler:
    case IntegratorKind::Symplectic: return 1.0;
    case IntegratorKind::Midpoint: return 2.0;
    case IntegratorKind::RK4: return 4.0;
  }
  return 0.0;
}

}  // namespace

const std::vector<IntegratorKind>& core_integrators() {
  static const std::vector<IntegratorKind> kinds = {IntegratorKind::Euler, IntegratorKind::Symplectic,
                                                    IntegratorKind::Midpoint, IntegratorKind::RK4};
  return kinds;
}

DynamicsEntry core_dynamics_entry(IntegratorKind kind) {
  DynamicsEntry e;
  e.name = integrator_name(kind);
  e.source = DynamicsSource::Core;
  e.integrator = kind;
  e.claimed_order = claimed_core_order(kind);
  e.evaluations_per_step = evaluations_per_step(kind);
  e.make = [kind](const Scene& scene) -> std::unique_ptr<DynamicsEngine> {
    Scene s = scene;
    s.integrator = kind;
    return std::make_unique<CoreDynamics>(s);
  };
  return e;
}

DynamicsEntry outside_dynamics_entry(const outside::OutsideEnginePtr& engine) {
  DynamicsEntry e;
  e.name = engine->name();
  e.source = DynamicsSource::Outside;
  e.claimed_order = engine->claimed_order().value_or(0.0);
  e.outside_engine = engine;
  e.make = [engine](const Scene& scene) {
    outside::Creation c = engine->create(scene);
    if (!c.simulation) throw std::runtime_error(outside::not_modelled_line(engine->name(), c.refusal));
    return std::move(c.simulation);
  };
  return e;
}

std::vector<DynamicsEntry> dynamics_engines(const DynamicsSources& sources, const outside::OutsideEngines* loaded,
                                            const ClassicCalibration& classic) {
  std::vector<DynamicsEntry> out;
  if (sources.core)
    for (IntegratorKind k : core_integrators()) out.push_back(core_dynamics_entry(k));
  if (sources.bullet)
    for (DynamicsEntry& e : bullet_dynamics_entries(classic)) out.push_back(std::move(e));
  if (sources.outside && loaded)
    for (const auto& e : loaded->with(&outside::Capabilities::dynamics)) out.push_back(outside_dynamics_entry(e));
  return out;
}

}  // namespace tecido::engines
