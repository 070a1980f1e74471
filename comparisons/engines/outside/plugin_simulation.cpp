#include "comparisons/engines/outside/plugin_simulation.h"

#include "comparisons/engines/outside/scene_arrays.h"

#include <cmath>

namespace tecido::outside {

PluginSimulation::PluginSimulation(const tecido_engine* engine, void* handle, std::size_t particles, double dt,
                                   std::shared_ptr<std::mutex> mutex, std::shared_ptr<const void> keep_alive)
    : engine_(engine), handle_(handle), dt_(dt), flat_x_(3 * particles), flat_v_(3 * particles),
      mutex_(std::move(mutex)), keep_alive_(std::move(keep_alive)) {
  read_state();
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
  for (std::size_t i = 0; i < flat_x_.size(); ++i)
    if (!std::isfinite(flat_x_[i]) || !std::isfinite(flat_v_[i])) failed_ = true;
}

bool PluginSimulation::advance(long long n) {
  if (failed_) return false;
  if (n <= 0) return true;
  int status;
  {
    auto lock = guard();
    status = engine_->step(handle_, dt_, static_cast<std::int64_t>(n));
  }
  if (status != 0) failed_ = true;
  steps_ += n;
  read_state();
  return !failed_;
}

}  // namespace tecido::outside
