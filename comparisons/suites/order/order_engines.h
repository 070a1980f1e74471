#pragma once
/// The dynamics engines the `order` suite measures, taken from the one registry
/// (comparisons/engines/dynamics_engines.h): a name, the order the engine claims, and how to build
/// it on a scene. Core's four integrators claim 1 (explicit and symplectic Euler), 2 (midpoint) and
/// 4 (RK4); an outside engine states its own. Bullet's engines are not measured here.
#include "comparisons/engines/dynamics_engine.h"
#include "comparisons/engines/dynamics_entry.h"
#include "comparisons/suites/suite.h"
#include "core/scene/scene.h"

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
  std::function<std::unique_ptr<engines::DynamicsEngine>(const Scene&)> make;
  bool outside = false;  ///< from outside tecido's tree (its wall time includes its door's calls)
};

/// A registry entry as an engine of this suite.
OrderEngine order_engine(const engines::DynamicsEntry& entry);

/// The registry's core engines (euler, symplectic, midpoint, rk4) and outside engines (ctx's; a
/// scene one refuses fails its check with "not modelled by NAME: why"), those ctx.selects() (none,
/// when --engines names only engines of other suites).
std::vector<OrderEngine> order_engines(const SuiteContext& ctx);

}  // namespace tecido::suites::order
