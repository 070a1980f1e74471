#pragma once
/// Extremes, group "resting contact" (RestingSettings): a particle released on a plane under
/// gravity, each integrator, for 1e5 steps; the symplectic run again with the scene shifted 1e6 m.
#include "comparisons/suites/stability/extremes.h"

namespace tecido::suites::stability {

/// stability/extremes/rest_max_sink and rest_max_jitter: the deepest below and the highest above the
/// plane over every run (an unstable run fails both with its step).
std::vector<CheckSpec> resting_checks(const Settings& s);
/// data["resting"] = {"max_speed", "max_drift"}: the largest |v| and displacement over the runs.
ExtremeResult run_resting(const Settings& s);

}  // namespace tecido::suites::stability
