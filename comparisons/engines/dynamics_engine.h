#pragma once
/// One interface for every engine that steps a core Scene's particles and springs: core itself
/// (core_dynamics.h), Bullet's deformable world and classic soft body (bullet_dynamics.h, over the
/// reference adapters), and outside engines (outside/). Suites drive them alike: step, read
/// positions and velocities in core's numbering, and list what the scene asks for that the engine
/// does not model, so a difference in modelling is reported, never hidden. The suites find them
/// in one registry (dynamics_engines.h).
#include "core/geometry/types.h"

#include <string>
#include <vector>

namespace tecido::engines {

class DynamicsEngine {
 public:
  virtual ~DynamicsEngine() = default;
  /// Advances one step of the scene's dt. Returns false when the state stopped being finite (or
  /// the engine failed); later calls do nothing and return false.
  virtual bool step() = 0;
  /// Advances n steps of the scene's dt; false as step(). Outside engines take the n steps in one
  /// call of their door (one round trip for a process) instead of n.
  virtual bool advance(long long n) {
    bool ok = true;
    for (long long i = 0; i < n && ok; ++i) ok = step();
    return ok;
  }
  /// Node positions [m] and velocities [m/s] in core's numbering (node i = scene particle i).
  virtual std::vector<Vec3> positions() const = 0;
  virtual std::vector<Vec3> velocities() const = 0;
  /// Scene features this engine does not reproduce, one line each ("<feature>: <why>"); empty
  /// when it models the whole scene.
  virtual std::vector<std::string> not_modelled() const = 0;
  /// Simulated time [s] and steps done.
  virtual double time() const = 0;
  virtual long long steps_done() const = 0;
};

}  // namespace tecido::engines
