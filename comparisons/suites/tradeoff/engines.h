#pragma once
/// The engines the `tradeoff` suite compares, each a name and a factory of an
/// engines::DynamicsEngine, all run by the one guarded fixed-time runner (reference/guarded_run.h):
/// every engine of the one registry (comparisons/engines/dynamics_engines.h), core's four
/// integrators, Bullet's seven engines and the outside engines, with this suite's names and ranges.
#include "comparisons/engines/dynamics_engine.h"
#include "comparisons/engines/dynamics_entry.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/tradeoff/settings.h"
#include "core/scene/scene.h"
#include "reference/guarded_run.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace tecido::suites::tradeoff {

struct TradeoffEngine {
  std::string name;                   ///< e.g. "core-rk4"
  double evaluations_per_step = 0.0;  ///< force evaluations per step, for the report (0 = not counted)
  /// Builds the engine on `scene` at its dt (the scene's integrator is the engine's business).
  /// May throw (the classic soft body when its kLST calibration fails): the run then fails with
  /// that reason.
  std::function<std::unique_ptr<engines::DynamicsEngine>(const Scene& scene)> make;
  /// The suite runs this engine only on cloths of at most max_n x max_n nodes and at the
  /// max_steps largest swept steps (0 = no limit); the points outside are not run.
  int max_n = 0;
  int max_steps = 0;
  /// Steps per call of advance() (0: step() by step()): an outside engine takes its steps this many
  /// per call of its door, so that a process pays a round trip per chunk, not per step. The stray
  /// check runs after each chunk; a failure is reported at the chunk's last step.
  long long door_chunk = 0;
  /// How an outside engine is reached (OutsideEngine::door()); empty for built-in engines.
  std::string door;

  /// `scene` (its dt ignored) from its initial state at step h for round(seconds / h) steps,
  /// through the guarded runner: failed at a non-finite state or a node more than stray_limit [m]
  /// from its start, or when the engine cannot be built.
  reference::GuardedRun run_guarded(const Scene& scene, double h, double seconds, double stray_limit = 1e3) const;
  /// The positions of run_guarded, nothing when it failed.
  std::optional<std::vector<Vec3>> run(const Scene& scene, double h, double seconds) const;
};

/// A registry entry as an engine of this suite: core's named "core-<integrator>", Bullet's with
/// their ranges from s.bullet, an outside engine with its door, chunk and s.outside's range.
TradeoffEngine tradeoff_engine(const engines::DynamicsEntry& entry, const Settings& s);

/// Core with integrator `kind` ("core-<integrator>").
TradeoffEngine core_tradeoff_engine(IntegratorKind kind);

/// Every engine, in report order: core's euler, symplectic, midpoint and rk4, Bullet's (their
/// ranges from s.bullet), then the outside engines with dynamics of `ctx` that it selects (none
/// when ctx is null).
std::vector<TradeoffEngine> tradeoff_engines(const Settings& s = Settings{}, const SuiteContext* ctx = nullptr);

/// Whether the suite leaves out engine e's point on the n x n cloth at the j-th swept step.
bool skipped(const TradeoffEngine& e, int n, std::size_t j);

}  // namespace tecido::suites::tradeoff
