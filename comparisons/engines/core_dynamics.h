#pragma once
/// Core's Simulation behind the DynamicsEngine interface (dynamics_engine.h), so suites run core,
/// Bullet and outside engines through one door.
#include "comparisons/engines/dynamics_engine.h"
#include "core/simulation/simulation.h"

namespace tecido::engines {

class CoreDynamics final : public DynamicsEngine {
 public:
  explicit CoreDynamics(const Scene& scene) : sim_(scene) {}
  bool step() override { return sim_.step(); }
  std::vector<Vec3> positions() const override { return sim_.particles().x; }
  std::vector<Vec3> velocities() const override { return sim_.particles().v; }
  std::vector<std::string> not_modelled() const override { return {}; }
  double time() const override { return sim_.time(); }
  long long steps_done() const override { return sim_.steps_done(); }
  const Simulation& simulation() const { return sim_; }

 private:
  Simulation sim_;
};

}  // namespace tecido::engines
