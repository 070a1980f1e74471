#pragma once
/// Extremes, group "near-zero rest length" (NearZeroSettings): springs of rest length 1e-9..1e-15 m
/// oscillating through their anchor, springs whose two ends coincide (the engine skips a spring
/// with |d| = 0, the one place its direction is undefined), and ends so close that |d|^2 is
/// subnormal or rounds to 0.
#include "comparisons/suites/stability/extremes.h"

namespace tecido::suites::stability {

/// stability/extremes/near_zero_nonfinite (runs or forces with NaN/Inf: a count, so a non-finite
/// run is its value) and zero_length_force (the force of a spring whose ends coincide).
std::vector<CheckSpec> near_zero_checks(const Settings& s);
/// data["near_zero"] = {"nonfinite", "runs", "deviation_over_l"}: how many of the runs and forces were
/// not finite, and each finite run's largest deviation from the l = 0 run over its l.
ExtremeResult run_near_zero(const Settings& s);

}  // namespace tecido::suites::stability
