#pragma once
/// Extremes, group "tunnelling" (TunnellingSettings): a particle falling from 1 m onto a 1 m x 1 m
/// plane of zero thickness, at each initial speed and step up to 10 s, every integrator.
#include "comparisons/suites/stability/extremes.h"

namespace tecido::suites::stability {

/// stability/extremes/tunnel_wrong_side_steps: steps ending below the plane, over every run (an
/// unstable run fails it with its step).
std::vector<CheckSpec> tunnelling_checks(const Settings& s);
/// One row per (speed, dt); data["tunnelling"] = {"wrong_side_steps", "runs", "max_dt"}.
ExtremeResult run_tunnelling(const Settings& s);

}  // namespace tecido::suites::stability
