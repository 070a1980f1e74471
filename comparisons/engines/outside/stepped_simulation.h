#pragma once
/// What every outside engine's simulation (a plug-in's, a process's, a Python object's) shares
/// behind engines::DynamicsEngine: step() is advance(1); advance(n) is one call into the engine
/// for n steps (`call_step`), after which the positions and velocities it handed back are the
/// state. A failed call or a non-finite coordinate ends the run: advance() returns false from
/// then on and the state stays the last one read. Time is steps x dt, as the engine was asked.
#include "comparisons/engines/dynamics_engine.h"

#include <string>
#include <utility>
#include <vector>

namespace tecido::outside {

class SteppedSimulation : public engines::DynamicsEngine {
 public:
  bool step() final { return advance(1); }
  bool advance(long long n) final {
    if (failed_) return false;
    if (n <= 0) return true;
    const bool ok = call_step(n);
    steps_ += n;
    failed_ = !ok || !finite_state();
    return !failed_;
  }
  std::vector<Vec3> positions() const final { return x_; }
  std::vector<Vec3> velocities() const final { return v_; }
  std::vector<std::string> not_modelled() const final { return {}; }
  double time() const final { return static_cast<double>(steps_) * dt_; }
  long long steps_done() const final { return steps_; }

 protected:
  explicit SteppedSimulation(double dt) : dt_(dt) {}
  /// The start, set by the derived constructor: the scene's state, or what the engine reports
  /// after create (a non-finite value there ends the run before its first step).
  void begin(std::vector<Vec3> x, std::vector<Vec3> v) {
    x_ = std::move(x);
    v_ = std::move(v);
    failed_ = !finite_state();
  }

  /// Asks the engine for `n` steps of dt() and replaces x_ and v_ (same sizes) with what it
  /// answers; false when the engine reports failure. Protocol errors throw, as the engine's
  /// other calls do.
  virtual bool call_step(long long n) = 0;
  double dt() const { return dt_; }

  std::vector<Vec3> x_, v_;

 private:
  bool finite_state() const {
    for (std::size_t i = 0; i < x_.size(); ++i)
      if (!x_[i].allFinite() || !v_[i].allFinite()) return false;
    return true;
  }
  double dt_;
  long long steps_ = 0;
  bool failed_ = false;
};

}  // namespace tecido::outside
