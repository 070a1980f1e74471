#pragma once
/// A Python engine's simulation (comparisons/engines/outside/stepped_simulation.h), as
/// ProcessSimulation is a process's: advance(n) is one call step(dt, n), whose positions and
/// velocities ((n, 3) each) are read back.
/// Holds the engine's scene lease until destroyed.
#include "comparisons/engines/outside/stepped_simulation.h"
#include "core/scene/scene.h"

#include <memory>
#include <vector>

namespace tecido::python {

class PythonEngine;

class PythonSimulation final : public outside::SteppedSimulation {
 public:
  /// After a successful create on `engine` (which holds the lease for this simulation).
  PythonSimulation(std::shared_ptr<PythonEngine> engine, const Scene& scene);
  ~PythonSimulation() override;

 private:
  bool call_step(long long n) override;
  std::shared_ptr<PythonEngine> engine_;
};

}  // namespace tecido::python
