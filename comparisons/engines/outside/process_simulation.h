#pragma once
/// A process engine's simulation behind engines::DynamicsEngine: step() is one round trip
/// {"op":"step","dt":h,"steps":1}, advance(n) one round trip of n steps. Holds the process's scene
/// lease (process_engine.h) until destroyed. A null (non-finite) coordinate in a reply ends the run.
#include "comparisons/engines/dynamics_engine.h"
#include "comparisons/engines/outside/process_engine.h"

#include <memory>
#include <vector>

namespace tecido::outside {

class ProcessSimulation final : public engines::DynamicsEngine {
 public:
  /// After a successful create on `engine` (which holds the lease for this simulation).
  ProcessSimulation(std::shared_ptr<ProcessEngine> engine, const Scene& scene);
  ~ProcessSimulation() override;

  bool step() override { return advance(1); }
  bool advance(long long n) override;
  std::vector<Vec3> positions() const override { return x_; }
  std::vector<Vec3> velocities() const override { return v_; }
  std::vector<std::string> not_modelled() const override { return {}; }
  double time() const override { return static_cast<double>(steps_) * dt_; }
  long long steps_done() const override { return steps_; }

 private:
  std::shared_ptr<ProcessEngine> engine_;
  double dt_;
  long long steps_ = 0;
  bool failed_ = false;
  std::vector<Vec3> x_, v_;
};

}  // namespace tecido::outside
