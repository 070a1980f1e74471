#pragma once
/// Extremes, group "offset": coordinates offset by 1e6..1e8 m (OffsetSettings). Each run is
/// compared with the same run at the origin; the error is a sum of per-step roundings of the stored
/// positions, bounded by about one ulp of the offset per step (checked).
#include "comparisons/suites/stability/extremes.h"

namespace tecido::suites::stability {

/// stability/extremes/offset_error_ulps_per_step.
std::vector<CheckSpec> offset_checks(const Settings& s);
/// Per offset, the oscillators and a particle dropped on a plane; data["offset"] holds each finite
/// run: {kind ("spring" or "drop"), offset, error, ulps_per_step} and for a spring rest_length,
/// amplitude and relative (error / amplitude).
ExtremeResult run_offset(const Settings& s);

}  // namespace tecido::suites::stability
