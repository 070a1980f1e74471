#include "comparisons/engines/outside/scene_lease.h"

#include "comparisons/engines/outside/engine_error.h"

namespace tecido::outside {

void SceneLease::take(const std::string& door, const std::string& holder) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (taken_ && holder_ == std::this_thread::get_id())
    throw EngineError(door, "op create",
                      "asked for a second simulation while one is running (" + holder + " holds one scene at a time)");
  free_.wait(lock, [&] { return !taken_; });
  taken_ = true;
  holder_ = std::this_thread::get_id();
}

void SceneLease::release() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    taken_ = false;
  }
  free_.notify_one();
}

}  // namespace tecido::outside
