#pragma once
/// One scene at a time, for an outside engine that holds a single simulation state (a JSON-lines
/// process, a Python object with create/step): a simulation takes the lease at create() and gives
/// it back when destroyed, so dynamics runs of such an engine run one after another. A thread that
/// asks for a second simulation while holding one gets an EngineError instead of a deadlock.
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

namespace tecido::outside {

class SceneLease {
 public:
  /// Waits until the scene is free and takes it. Throws EngineError(`door`, "op create", ...)
  /// when this thread holds it already; `holder` says who holds the scene ("the process").
  void take(const std::string& door, const std::string& holder);
  void release();

 private:
  std::mutex mutex_;
  std::condition_variable free_;
  bool taken_ = false;
  std::thread::id holder_;
};

}  // namespace tecido::outside
