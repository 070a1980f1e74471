#include "comparisons/engines/outside/plugin_simulation.h"

#include "comparisons/engines/outside/scene_arrays.h"

namespace tecido::outside {

PluginSimulation::PluginSimulation(const tecido_engine* engine, void* handle, std::size_t particles, double dt,
                                   std::shared_ptr<std::mutex> mutex, std::shared_ptr<const void> keep_alive)
    : SteppedSimulation(dt), engine_(engine), handle_(handle), flat_x_(3 * particles), flat_v_(3 * particles),
      mutex_(std::move(mutex)), keep_alive_(std::move(keep_alive)) {
  read_state();
  begin(std::move(x_), std::move(v_));
}

PluginSimulation::~PluginSimulation() {
  auto lock = guard();
  engine_->destroy(handle_);
}

std::unique_lock<std::mutex> PluginSimulation::guard() const {
  return mutex_ ? std::unique_lock<std::mutex>(*mutex_) : std::unique_lock<std::mutex>();
}

void PluginSimulation::read_state() {
  {
    auto lock = guard();
    engine_->read(handle_, flat_x_.data(), flat_v_.data());
  }
  x_ = points_from_flat(flat_x_);
  v_ = points_from_flat(flat_v_);
}

bool PluginSimulation::call_step(long long n) {
  int status;
  {
    auto lock = guard();
    status = engine_->step(handle_, dt(), static_cast<std::int64_t>(n));
  }
  read_state();
  return status == 0;
}

}  // namespace tecido::outside
