#pragma once
/// A Python engine's simulation behind engines::DynamicsEngine, as ProcessSimulation is a
/// process's: step() is one call step(dt, 1), advance(n) one call step(dt, n); the positions and
/// velocities it returns are read back ((n, 3) each; None or a non-finite value ends the run).
/// Holds the engine's scene lease until destroyed.
#include "comparisons/engines/dynamics_engine.h"
#include "core/scene/scene.h"

#include <memory>
#include <vector>

namespace tecido::python {

class PythonEngine;

class PythonSimulation final : public engines::DynamicsEngine {
 public:
  /// After a successful create on `engine` (which holds the lease for this simulation).
  PythonSimulation(std::shared_ptr<PythonEngine> engine, const Scene& scene);
  ~PythonSimulation() override;

  bool step() override { return advance(1); }
  bool advance(long long n) override;
  std::vector<Vec3> positions() const override { return x_; }
  std::vector<Vec3> velocities() const override { return v_; }
  std::vector<std::string> not_modelled() const override { return {}; }
  double time() const override { return static_cast<double>(steps_) * dt_; }
  long long steps_done() const override { return steps_; }

 private:
  std::shared_ptr<PythonEngine> engine_;
  double dt_;
  long long steps_ = 0;
  bool failed_ = false;
  std::vector<Vec3> x_, v_;
};

}  // namespace tecido::python
