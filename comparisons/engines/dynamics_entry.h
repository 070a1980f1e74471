#pragma once
/// One entry of the dynamics registry (dynamics_engines.h): an engine's name, where it comes from,
/// what it claims, and how to build it on a scene behind the DynamicsEngine interface.
#include "comparisons/engines/dynamics_engine.h"
#include "comparisons/engines/outside/outside_engine.h"
#include "core/dynamics/integrator.h"
#include "core/scene/scene.h"

#include <functional>
#include <memory>
#include <string>

namespace tecido::engines {

/// Where a dynamics engine comes from; each suite asks the registry for the sources it can use.
enum class DynamicsSource {
  Core,     ///< core's Simulation with one of its integrators (core_dynamics.h)
  Bullet,   ///< Bullet's deformable world or classic soft body (bullet_dynamics_engines.h)
  Outside,  ///< a plug-in or a JSON-lines process with dynamics (--plugin, --engine-cmd)
};

struct DynamicsEntry {
  /// Core: the integrator's name ("euler", "symplectic", "midpoint", "rk4"); Bullet: e.g.
  /// "bullet-classic-it4"; outside: the name it was loaded as.
  std::string name;
  DynamicsSource source = DynamicsSource::Core;
  /// Core: the integrator set on every scene it builds. Bullet: symplectic Euler, the method its
  /// scenes are set to. Outside: unused (the method is the engine's).
  IntegratorKind integrator = IntegratorKind::Symplectic;
  /// The order of accuracy the engine claims; 0: none.
  double claimed_order = 0.0;
  /// Force evaluations per step, for reports; 0: not counted.
  double evaluations_per_step = 0.0;
  /// Builds the engine on a scene at its dt. Throws when it cannot: an outside engine refusing
  /// the scene ("not modelled by NAME: why"), the classic soft body when its kLST calibration fails.
  std::function<std::unique_ptr<DynamicsEngine>(const Scene&)> make;
  /// Outside engines: the engine itself (its door, its own calls); null otherwise.
  outside::OutsideEnginePtr outside_engine;
};

}  // namespace tecido::engines
