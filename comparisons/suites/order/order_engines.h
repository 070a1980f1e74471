#pragma once
/// The dynamics engines the `order` suite measures: a name, the order the engine claims, and how
/// to build it on a scene. Core's four integrators claim 1 (explicit and symplectic Euler), 2
/// (midpoint) and 4 (RK4); an outside engine states its own.
#include "core/scene/scene.h"
#include "reference/dynamics_engine.h"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace tecido::suites::order {

struct OrderEngine {
  std::string name;
  double claimed_order = 0.0;  ///< the order the suite checks the fit against
  std::function<std::unique_ptr<reference::DynamicsEngine>(const Scene&)> make;
};

/// euler, symplectic, midpoint, rk4: core's Simulation with the scene's integrator set.
std::vector<OrderEngine> core_order_engines();

}  // namespace tecido::suites::order
