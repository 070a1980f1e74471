#pragma once
/// The stages of core's continuous collision test in order (ccd/ccd.h has the guarantees):
/// non-finite input, swept boxes, kinetic boxes, the system of differences, the coplanarity
/// cubic on [0, 1], then the time search with the inclusion search as its fallback.
#include "core/geometry/ccd/query.h"
#include "core/geometry/ccd/settings.h"

namespace tecido {

/// Settings brought into their documented ranges (ccd/settings.h): time tolerance rounded
/// down to a power of two in [2^-40, 2^-2], distance tolerance in [2^-36, 2^-4], max_boxes
/// >= 1; NaN fields take their defaults.
CcdSettings ccd_clamped(const CcdSettings& s);

/// Runs the stages on q as q.kind says, with clamped settings.
CcdAnswer ccd_pipeline(const CcdQuery& q, const CcdSettings& clamped);

/// The stages after the boxes (the system, the cubic, the time search), for a caller that has
/// already checked that q is finite and that its swept and kinetic boxes may meet: then the
/// answer is ccd_pipeline's. Default settings.
CcdAnswer ccd_after_boxes(const CcdQuery& q);

}  // namespace tecido
