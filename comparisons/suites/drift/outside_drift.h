#pragma once
/// Outside dynamics engines (--plugin, --engine-cmd) in the `drift` suite: each runs every
/// conservative scene (scenes.h) for the same steps as core's integrators, sampled as theirs, so
/// its energy, momentum and angular momentum errors stand in the same table's terms beside core's.
/// One case per (engine, scene), after the suite's own cases, engine-major.
///
/// Checked per run: `drift/<scene>/<engine>/momentum` within /drift/momentum_rel, as core's: every
/// force evaluation of central springs sums to zero, so any integrator whose update is linear in
/// the forces conserves momentum to round-off. Energy and angular momentum depend on the method,
/// which tecido does not know: reported, not checked. The checks are declared from the engines
/// named, before any run; a scene the engine refuses fails its check with "not modelled by NAME".
#include "comparisons/engines/outside/outside_engine.h"
#include "comparisons/io/json_reader.h"
#include "comparisons/suites/check.h"
#include "comparisons/suites/drift/invariants.h"
#include "comparisons/suites/drift/scenes.h"
#include "comparisons/suites/drift/settings.h"
#include "comparisons/suites/tolerances.h"

#include <string>
#include <vector>

namespace tecido::suites::drift {

/// Runs `engine` on `scene` for s.steps steps, one call of its door per s.sample_every steps, and
/// measures as run_invariants (no angular momentum theory: the method is the engine's). A failed
/// advance ends the run, unstable at that call's last step. Throws std::runtime_error
/// ("not modelled by NAME: why") when the engine refuses the scene.
InvariantRun run_outside_invariants(outside::OutsideEngine& engine, const Scene& scene, const Settings& s);

/// "drift/<scene>/<engine>/"
std::string outside_prefix(const std::string& scene, const std::string& engine);

/// The momentum check of every (scene, engine).
void declare_outside_drift(CheckList& checks, const std::vector<Conservative>& scenes,
                           const std::vector<outside::OutsideEnginePtr>& engines, const Tolerances& tol);

/// The outside cases' results (engine-major, then scene) into their checks, report data
/// (data[scene][engine]) and a Markdown table with each engine's door; "" without outside engines.
std::string outside_drift_markdown(const std::vector<Conservative>& scenes,
                                   const std::vector<outside::OutsideEnginePtr>& engines,
                                   const std::vector<io::Json>& results, CheckList& checks, io::Json& data);

}  // namespace tecido::suites::drift
