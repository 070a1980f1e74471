#pragma once
/// The dynamics engines the `order` suite measures: a name, the order the engine claims, and how
/// to build it on a scene. Core's four integrators claim 1 (explicit and symplectic Euler), 2
/// (midpoint) and 4 (RK4); an outside engine states its own.
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/suites/suite.h"
#include "core/scene/scene.h"
#include "reference/dynamics_engine.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tecido::suites::order {

struct OrderEngine {
  std::string name;
  /// The order the suite checks the fit against; 0: the engine claims none (its fit is reported,
  /// not checked).
  double claimed_order = 0.0;
  /// Builds the engine on a scene; throws when it cannot (an outside engine refusing the scene).
  std::function<std::unique_ptr<reference::DynamicsEngine>(const Scene&)> make;
  bool outside = false;  ///< from outside tecido's tree (its wall time includes its door's calls)
};

/// euler, symplectic, midpoint, rk4: core's Simulation with the scene's integrator set.
std::vector<OrderEngine> core_order_engines();

/// An outside dynamics engine, claiming the order it claims (0 when none). A scene it refuses
/// throws std::runtime_error("not modelled by NAME: why"), which fails its check with that reason.
OrderEngine outside_order_engine(const outside::OutsideEnginePtr& engine);

/// core's four and every outside dynamics engine of ctx, those ctx.selects() (none, when --engines
/// names only engines of other suites).
std::vector<OrderEngine> order_engines(const SuiteContext& ctx);

}  // namespace tecido::suites::order
