#pragma once
/// A plug-in engine's simulation (create/step/read/destroy of include/tecido/plugin.h;
/// stepped_simulation.h): advance(n) is step(sim, dt, n) in one call, then read(); a nonzero
/// return ends the run.
#include "comparisons/engines/outside/stepped_simulation.h"

#include <tecido/plugin.h>

#include <memory>
#include <mutex>
#include <vector>

namespace tecido::outside {

class PluginSimulation final : public SteppedSimulation {
 public:
  /// Takes ownership of `handle` (destroyed with the engine's destroy()). `mutex`, when set, is
  /// held around every call into the plug-in. `keep_alive` keeps the library loaded.
  PluginSimulation(const tecido_engine* engine, void* handle, std::size_t particles, double dt,
                   std::shared_ptr<std::mutex> mutex, std::shared_ptr<const void> keep_alive);
  ~PluginSimulation() override;

 private:
  bool call_step(long long n) override;
  void read_state();
  std::unique_lock<std::mutex> guard() const;
  const tecido_engine* engine_;
  void* handle_;
  std::vector<double> flat_x_, flat_v_;
  std::shared_ptr<std::mutex> mutex_;
  std::shared_ptr<const void> keep_alive_;
};

}  // namespace tecido::outside
