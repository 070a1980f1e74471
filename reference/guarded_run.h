#pragma once
/// The one guarded fixed-time runner for every dynamics engine: anything with step() (false once
/// the state is not finite) and positions() (core's numbering), so Bullet's deformable world and
/// classic soft body here, and every engine behind the suites' DynamicsEngine interface
/// (comparisons/engines/dynamics_engine.h: core's Simulation, Bullet's, outside engines) alike.
/// It tells a blow-up from a result the same way for all: a step that reports a non-finite state,
/// or a node far from its start. The second test is what catches Bullet, which
/// zeroes NaN velocity increments and clamps speeds, so that a run that blew up stays finite
/// (docs/dependencies.md). The step count is fixed, so a diverging run never hangs.
/// Header-only and Bullet-free.
#include "core/geometry/types.h"

#include <cmath>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace tecido::reference {

/// What a guarded run returned.
struct GuardedRun {
  std::optional<std::vector<Vec3>> x;  ///< final positions (core's numbering); empty when the run failed
  long long failed_at_step = 0;        ///< 1-based step at which the failure was seen (0: none)
  std::string reason;                  ///< why it failed, e.g. "non-finite state at step 12"
};

/// round(seconds / h): the steps of a fixed-time run at step h.
inline long long fixed_time_steps(double seconds, double h) { return std::llround(seconds / h); }

/// True when some node is farther than `limit` [m] from its position in x0 (or not finite).
inline bool strayed(const std::vector<Vec3>& x, const std::vector<Vec3>& x0, double limit) {
  const double limit2 = limit * limit;
  for (std::size_t k = 0; k < x.size(); ++k)
    if (!((x[k] - x0[k]).squaredNorm() <= limit2)) return true;
  return false;
}

/// Steps `engine` `steps` times from its current state. The run fails at the first step that
/// returns false (a non-finite state), or when a node is farther than `stray_limit` [m] from its
/// position in x0, checked every `check_every` steps (positions() copies, so not at every step)
/// and after the last; otherwise the result holds the final positions.
template <class Engine>
GuardedRun run_guarded(Engine& engine, const std::vector<Vec3>& x0, long long steps, double stray_limit,
                       long long check_every = 64) {
  GuardedRun r;
  auto fail = [&](long long step, const std::string& why) {
    r.failed_at_step = step;
    r.reason = why + " at step " + std::to_string(step);
    return r;
  };
  auto stray = [&] {
    std::ostringstream s;
    s << "a node more than " << stray_limit << " m from its start";
    return s.str();
  };
  for (long long i = 1; i <= steps; ++i) {
    if (!engine.step()) return fail(i, "non-finite state");
    if (i % check_every == 0 && strayed(engine.positions(), x0, stray_limit)) return fail(i, stray());
  }
  std::vector<Vec3> x = engine.positions();
  if (strayed(x, x0, stray_limit)) return fail(steps, stray());
  r.x = std::move(x);
  return r;
}

}  // namespace tecido::reference
