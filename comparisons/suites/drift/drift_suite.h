#pragma once
/// Suite `drift`: (a) energy, momentum and angular momentum over long runs per integrator on
/// conservative scenes, against what theory says each integrator conserves; (b) core against
/// Bullet on identical cloth scenes (reference build): the deformable twin step by step, a cloth
/// falling onto a floor, the classic soft body's kLST calibration and its check at another load.
///
/// Layout: settings.h (what runs), theory.* (the predictions), scenes.* (the scenes), invariants.*
/// (one invariants run), outside_drift.* (outside dynamics engines from --plugin and --engine-cmd
/// on the same scenes, their cases after the suite's own), bullet_cases.* (the Bullet case groups),
/// drift_report.* (tables, plots, prose); this file lists the cases, declares the checks and
/// assembles.
#include "comparisons/suites/drift/settings.h"
#include "comparisons/suites/suite.h"
#include "comparisons/suites/sweep.h"

#include <functional>
#include <string>
#include <vector>

namespace tecido::suites {

namespace drift {

/// One case of the sweep: its label and how to run it (a pure function of the settings).
struct DriftCase {
  std::string label;  ///< "two-body-3d/euler", "twin", ...
  std::function<io::Json()> run;
};

/// The case table, in index order: every (conservative scene, integrator) pair, scene-major, in
/// the order euler, symplectic, midpoint, rk4; then, in the reference build, the Bullet groups
/// twin, falling, classic, wind.
std::vector<DriftCase> drift_cases(const Settings& s, std::uint64_t seed);

/// Every check the suite reports, declared from the settings and the tolerance file alone.
CheckList declare_drift_checks(const Settings& s, std::uint64_t seed, const Tolerances& tol);

}  // namespace drift

/// The suite as a sweep over drift::drift_cases.
Sweep drift_sweep(const SuiteContext& ctx);
SuiteResult run_drift_suite(const SuiteContext& ctx);

}  // namespace tecido::suites
