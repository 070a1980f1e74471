#pragma once
/// The one registry of dynamics engines: every engine that steps a core Scene behind the
/// DynamicsEngine interface (dynamics_engine.h), in one order: core's four integrators, Bullet's
/// seven engines (bullet_dynamics_engines.h), then the outside engines with dynamics (plug-ins and
/// JSON-lines processes, outside/), in load order. The dynamics suites (order, drift, stability,
/// tradeoff) ask here for the sources they can use instead of building lists of their own.
#include "comparisons/engines/classic_calibration.h"
#include "comparisons/engines/dynamics_entry.h"
#include "comparisons/engines/outside/outside_engines.h"

#include <vector>

namespace tecido::engines {

/// Which sources a suite takes from the registry.
struct DynamicsSources {
  bool core = false;
  bool bullet = false;
  bool outside = false;
};

/// The registry's engines from `sources`, in the registry's order. `loaded` (may be null) holds
/// the engines loaded for this run; `classic` sets how Bullet's classic soft body calibrates kLST.
std::vector<DynamicsEntry> dynamics_engines(const DynamicsSources& sources, const outside::OutsideEngines* loaded,
                                            const ClassicCalibration& classic = {});

/// Core's Simulation with integrator `kind`, claiming its order (1 for both Euler methods, 2 for
/// midpoint, 4 for RK4).
DynamicsEntry core_dynamics_entry(IntegratorKind kind);
/// Core's integrators in the registry's order: euler, symplectic, midpoint, rk4.
const std::vector<IntegratorKind>& core_integrators();
/// An outside engine with dynamics, claiming what it claims (0 when nothing). Building it on a
/// scene it refuses throws std::runtime_error("not modelled by NAME: why").
DynamicsEntry outside_dynamics_entry(const outside::OutsideEnginePtr& engine);

}  // namespace tecido::engines
