#pragma once
/// A process engine's simulation (stepped_simulation.h): advance(n) is one round trip
/// {"op":"step","dt":h,"steps":n}. Holds the process's scene
/// lease (process_engine.h) until destroyed. A null (non-finite) coordinate in a reply ends the run.
#include "comparisons/engines/outside/process_engine.h"
#include "comparisons/engines/outside/stepped_simulation.h"

#include <memory>
#include <vector>

namespace tecido::outside {

class ProcessSimulation final : public SteppedSimulation {
 public:
  /// After a successful create on `engine` (which holds the lease for this simulation).
  ProcessSimulation(std::shared_ptr<ProcessEngine> engine, const Scene& scene);
  ~ProcessSimulation() override;

 private:
  bool call_step(long long n) override;
  std::shared_ptr<ProcessEngine> engine_;
};

}  // namespace tecido::outside
