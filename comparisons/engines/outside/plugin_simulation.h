#pragma once
/// A plug-in engine's simulation (create/step/read/destroy of include/tecido/plugin.h) behind
/// engines::DynamicsEngine: step() is step(sim, dt, 1), advance(n) is step(sim, dt, n) in one
/// call; positions and velocities are read back after each call, and a non-finite value or a
/// nonzero return ends the run (step() and advance() return false from then on).
#include "comparisons/engines/dynamics_engine.h"

#include <tecido/plugin.h>

#include <memory>
#include <mutex>
#include <vector>

namespace tecido::outside {

class PluginSimulation final : public engines::DynamicsEngine {
 public:
  /// Takes ownership of `handle` (destroyed with the engine's destroy()). `mutex`, when set, is
  /// held around every call into the plug-in. `keep_alive` keeps the library loaded.
  PluginSimulation(const tecido_engine* engine, void* handle, std::size_t particles, double dt,
                   std::shared_ptr<std::mutex> mutex, std::shared_ptr<const void> keep_alive);
  ~PluginSimulation() override;

  bool step() override { return advance(1); }
  bool advance(long long n) override;
  std::vector<Vec3> positions() const override { return x_; }
  std::vector<Vec3> velocities() const override { return v_; }
  std::vector<std::string> not_modelled() const override { return {}; }
  double time() const override { return static_cast<double>(steps_) * dt_; }
  long long steps_done() const override { return steps_; }

 private:
  void read_state();
  std::unique_lock<std::mutex> guard() const;
  const tecido_engine* engine_;
  void* handle_;
  double dt_;
  long long steps_ = 0;
  bool failed_ = false;
  std::vector<Vec3> x_, v_;
  std::vector<double> flat_x_, flat_v_;
  std::shared_ptr<std::mutex> mutex_;
  std::shared_ptr<const void> keep_alive_;
};

}  // namespace tecido::outside
